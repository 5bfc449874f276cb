//! Solving a map's grid. The rows are cut into runs solved in parallel;
//! along a run each point is first tried from where the point before it
//! was reached (the base where it stood, the same posture), then searched
//! as a reach would be, with that neighbour's base moved as the point
//! moved as the search's last resort. With neighbour starts the search's
//! retry (`bases::search`) waits: first the reached region grows into its
//! neighbours, round after round (each point not reached next to one
//! newly reached is tried from it, the same way, with a steering descent
//! as well), then each point still not reached whose search was blocked
//! is retried from its blocked placements, in waves of every eighth point
//! (diagonally), the region growing again from what each wave gains;
//! last, the points in gaps (runs not reached with a reached point at
//! either end, along a row or a column) and at the edge of the reached
//! region against a board are searched harder, and the region grows
//! again. Every round works from the answers of the round before, so the
//! order the threads take points in never matters.

use std::cell::RefCell;

use nalgebra::{Point3, Vector3};
use rayon::prelude::*;

use super::common::{mix_seed, Reaching};
use super::grid_settings::GridSettings;
use super::why::{Failed, Found};
use crate::bases::retry;
use crate::collision::Obstacles;
use crate::engine::{KeptProofs, SolvesFor};
use crate::kinematics::Chain;
use crate::plugin::{
    BasePose, Descents, Placement, PreparedBase, ReachQuery, Retry, Search, Subject, TaskInput,
};
use crate::report::{MapCell, MapReport, TaskReport};
use crate::scene::{Blocked, Blocker, Grid, GridCell, IkSolution, Surface};

/// Whether a point is reached (or seen), given where the base stood and
/// the posture found, and the point.
pub(super) type Judge<'a> = dyn Fn(&Placement, Point3<f64>) -> bool + Sync + 'a;

/// What a map (or a gaze map) asks of each point of its grid.
pub(super) struct MapAsked<'a> {
    pub reaching: &'a Reaching,
    pub grid: &'a GridSettings,
    /// The chain whose effector goes to each point.
    pub chain: &'a Chain,
    /// The obstacles its links keep out of.
    pub obstacles: Option<&'a Obstacles>,
    /// `reach` or `gaze`.
    pub of: &'static str,
    /// From each point of the surface to where the effector goes (a hand
    /// touches a point with its side, a hand's radius out of it; the eyes
    /// look at the point itself).
    pub lift_mm: Vector3<f64>,
    /// Whether to find why each point not reached was not, as a reach's
    /// why is found (`why.rs`).
    pub why: bool,
    /// The points already answered (by the other hand, for a map with
    /// either hand), by index: left unsolved, and not grown into.
    pub settled: Option<&'a [bool]>,
}

/// A map of the task's surface: each point's placement found as for a
/// reach of the chain's effector, judged by `judge`.
pub(super) fn run_map(
    input: &TaskInput<'_>,
    asked: &MapAsked<'_>,
    judge: &Judge<'_>,
) -> TaskReport {
    let Subject::Surface(surface) = input.subject else {
        unreachable!("the checker gives a map a surface")
    };
    TaskReport::Map(map_report(input, surface, asked, judge))
}

/// The most points of a row solved one after another, each from the
/// last: the rest of the row is another run, solved in parallel.
const RUN: usize = 32;

/// The waves the retries are made in: wave `k` retries the points whose
/// row and column add up to `k` modulo this, and the reached region grows
/// from what each wave gains before the next, so that along a row where
/// one retry in several finds the way, the rest are reached from it
/// rather than each retried (the answers are those of retrying every
/// point, or more).
const WAVES: usize = 8;

/// How many times harder a point in a gap (points not reached between
/// two that are, along a row or a column) or at a board's edge is
/// searched: so many cold searches, each retrying so many times as many
/// blocked placements.
const HARDER: usize = 4;

/// The widest a gap may be, from one reached end to the other: the
/// 100-150 mm over which a search's misses alternate with its reaches
/// along a wall. A run not reached that is wider is a region the person
/// does not reach, not a miss (searching each of its points four times
/// harder took an 816-point map of a deep shelf from 3.3 s to 19 s, and
/// reached no point more).
const GAP_SPAN_MM: f64 = 150.0;

/// The most points a gap may hold however far apart they are: on a
/// coarse map (`examples/population.reach`, 100 mm) a miss spans whole
/// points, and gaps of up to three hold every point the harder search
/// gains there.
const GAP_POINTS: usize = 3;

/// Where a point was reached, and the point (where the effector went).
struct Reached {
    placement: Placement,
    point_mm: Point3<f64>,
}

/// One point's answer: its cell of the report, and where it was reached.
struct Solved {
    cell: MapCell,
    reached: Option<Reached>,
    /// Where it was not: the blocked placements its search's retry, left
    /// for later, starts from.
    blocked: Vec<Blocked>,
    /// Where it was not and the map asks why: the closest placement found
    /// (boxed: a map of 100,000 points keeps one `Solved` a point).
    closest: Option<Box<Placement>>,
    /// Where it was not: what the closest posture went through, where it
    /// came within the tolerance.
    through: Option<Blocker>,
}

/// What every point of one map is solved with.
struct GridRun<'a> {
    input: &'a TaskInput<'a>,
    asked: &'a MapAsked<'a>,
    judge: &'a Judge<'a>,
    prepared: Box<dyn PreparedBase + 'a>,
    proofs: KeptProofs<'a>,
    /// Where the map's solves are kept (watch mode).
    solves: Option<SolvesFor<'a>>,
}

/// The map of `surface`: each point of its grid solved as `asked`,
/// judged by `judge`.
pub(super) fn map_report(
    input: &TaskInput<'_>,
    surface: &Surface,
    asked: &MapAsked<'_>,
    judge: &Judge<'_>,
) -> MapReport {
    let grid = surface.grid(asked.grid.step_mm);
    input.progress.add_work(grid.cells.len() as u64);
    let run = GridRun {
        input,
        asked,
        judge,
        prepared: input.base.prepare(input.room, asked.chain, input.allowance),
        proofs: KeptProofs::new(asked.chain, input.base.own_body(), input.allowance),
        solves: (input.solves).map(|s| s.of(asked.chain, asked.obstacles, input.base.own_body())),
    };
    let mut solved = run.first_pass(&grid);
    run.proofs.settle();
    // A run past its bound on solver work is thrown away: what is left of
    // the map is not worked out.
    let stopped = || input.allowance.exhausted();
    if asked.grid.neighbour_starts && !stopped() {
        let reached: Vec<usize> = (0..solved.len())
            .filter(|&i| solved[i].reached.is_some())
            .collect();
        run.grow(&grid, &mut solved, reached, Steer::AsTheNeighbour);
        for wave in (0..WAVES).take_while(|_| !stopped()) {
            let gained = run.retry_waiting(&grid, &mut solved, wave);
            run.proofs.settle();
            run.grow(&grid, &mut solved, gained, Steer::Always);
        }
        run.fill_gaps(&grid, &mut solved);
    }
    if asked.why && !stopped() {
        run.find_why(&grid, &mut solved);
    }
    let cells = solved.into_iter().map(|s| s.cell).collect();
    let reaching = asked.reaching;
    let mut report = MapReport::new(
        surface,
        input.person,
        &reaching.common.solver.name,
        asked.grid.step_mm,
        reaching.common.tolerance_mm,
        &grid,
        cells,
    );
    report.of = asked.of;
    report.effector = asked.chain.effector_name.clone();
    report.point = asked.chain.measured_to();
    report
}

impl<'a> GridRun<'a> {
    /// Runs of a row in parallel; along a run, each point tried on from
    /// the last point reached, then searched. Runs, not whole rows, so
    /// that a few hard rows (the lowest, where the legs are in the way)
    /// do not keep one thread busy while the others wait.
    fn first_pass(&self, grid: &Grid) -> Vec<Solved> {
        let runs: Vec<&[GridCell]> = grid
            .cells
            .chunks(grid.columns.max(1))
            .flat_map(|row| row.chunks(RUN))
            .collect();
        runs.par_iter()
            // One run a piece of work: rayon splits a range only until it
            // has a few pieces per thread, and a piece not stolen is solved
            // whole, so the hard rows at the bottom could end on one thread.
            .with_max_len(1)
            .flat_map_iter(|run| {
                // The last point of the run reached, by its index.
                let mut solved: Vec<Solved> = Vec::with_capacity(run.len());
                let mut last: Option<usize> = None;
                // The run's descents, kept from point to point.
                let descents = RefCell::new(Descents::default());
                for cell in *run {
                    if self.settled(cell.row * grid.columns + cell.column) {
                        solved.push(self.unsolved(cell));
                        self.input.progress.advance(1);
                        continue;
                    }
                    let neighbour = last
                        .filter(|_| self.asked.grid.neighbour_starts)
                        .and_then(|i| solved[i].reached.as_ref());
                    let point = self.solve(cell, neighbour, &descents);
                    self.input.progress.advance(1);
                    if point.reached.is_some() {
                        last = Some(solved.len());
                    }
                    solved.push(point);
                }
                solved
            })
            .collect()
    }

    /// The query of `cell`'s point, with `neighbour`'s base moved as the
    /// point moved as its search's last resort.
    fn query<'q>(&'q self, cell: &GridCell, neighbour: Option<&'q Reached>) -> ReachQuery<'q> {
        let reaching = self.asked.reaching;
        let target_room_mm = cell.point_mm + self.asked.lift_mm;
        let seed = mix_seed(reaching.common.seed, "map");
        ReachQuery {
            last_resort: neighbour.and_then(|n| self.carried(n, &target_room_mm)),
            from_rest: false,
            solves: self.solves,
            ..reaching
                .query(
                    target_room_mm,
                    seed,
                    Search::FirstReaching,
                    self.asked.obstacles,
                    self.input.base.own_body(),
                    self.input.allowance,
                )
                .keeping_proofs(&self.proofs)
        }
    }

    /// `cell`'s point: from `neighbour` (the last point reached in its
    /// run), else searched, reusing the run's `descents` (with neighbour
    /// starts).
    fn solve(
        &self,
        cell: &GridCell,
        neighbour: Option<&Reached>,
        descents: &RefCell<Descents>,
    ) -> Solved {
        // Without neighbour starts each point is solved cold, on its own.
        let query = ReachQuery {
            descents: Some(descents).filter(|_| self.asked.grid.neighbour_starts),
            ..self.query(cell, neighbour)
        };
        if self.input.allowance.exhausted() {
            // The run is thrown away: the point is left unsolved.
            return self.unsolved(cell);
        }
        let counts = |p: &Placement| (self.judge)(p, cell.point_mm);
        let on = neighbour
            .map(|n| &n.placement)
            .filter(|p| self.prepared.admits(&p.pose, &query.target_room_mm))
            .and_then(|p| self.on_from(&query, p, &counts, Steer::AsTheNeighbour));
        if let Some(placement) = on {
            return self.solved(cell, placement, query.target_room_mm);
        }
        let solver = self.asked.reaching.solver.as_ref();
        if !self.asked.grid.neighbour_starts {
            let placement = self.prepared.reach(&query, solver);
            return self.solved(cell, placement, query.target_room_mm);
        }
        let (placement, blocked) = self.prepared.reach_retrying_later(&query, solver);
        let mut point = self.solved(cell, placement, query.target_room_mm);
        if point.reached.is_none() {
            point.blocked = blocked;
        }
        point
    }

    /// `cell`'s point left unsolved: settled already, or the run thrown
    /// away.
    fn unsolved(&self, cell: &GridCell) -> Solved {
        let placement = Placement {
            pose: BasePose {
                position_mm: Point3::origin(),
                heading_rad: 0.0,
            },
            solution: IkSolution::unsolved(self.asked.chain),
            retried: false,
        };
        self.solved(cell, placement, cell.point_mm + self.asked.lift_mm)
    }

    /// Whether point `i` was answered before this map (by the other hand).
    fn settled(&self, i: usize) -> bool {
        self.asked.settled.is_some_and(|s| s[i])
    }

    fn solved(&self, cell: &GridCell, placement: Placement, point_mm: Point3<f64>) -> Solved {
        let counts = (self.judge)(&placement, cell.point_mm);
        let mut cell = MapCell::new(cell, &placement, self.asked.chain, counts);
        let mut through = None;
        if !counts && self.asked.of == "reach" {
            through = self.through(&placement);
            cell.set_through(through.map(|b| self.input.names(self.asked.chain).blocker(b)));
        }
        let (reached, closest) = if counts {
            let reached = Reached {
                placement,
                point_mm,
            };
            (Some(reached), None)
        } else {
            (None, self.asked.why.then(|| Box::new(placement)))
        };
        Solved {
            cell,
            reached,
            blocked: Vec::new(),
            closest,
            through,
        }
    }

    /// What the closest posture of a point not reached passes through,
    /// where it came within the tolerance.
    fn through(&self, placement: &Placement) -> Option<Blocker> {
        let solution = &placement.solution;
        let collision = solution.collision.as_ref()?;
        let tolerance_mm = self.asked.reaching.common.tolerance_mm;
        (solution.distance_mm <= tolerance_mm).then_some(collision.blocker)
    }

    /// Why each point not reached was not, found as a reach's is
    /// (searched again without what may have stopped it); a point such a
    /// search finds a posture for after all is reached with it.
    fn find_why(&self, grid: &Grid, solved: &mut [Solved]) {
        let unreached: Vec<usize> = (0..solved.len())
            .filter(|&i| solved[i].reached.is_none() && !self.settled(i))
            .collect();
        self.input.progress.add_work(unreached.len() as u64);
        let found: Vec<(usize, Point3<f64>, Found)> = unreached
            .par_iter()
            .with_max_len(1)
            .filter_map(|&i| {
                let closest = solved[i].closest.as_ref()?;
                let query = self.query(&grid.cells[i], None);
                let failed = Failed {
                    reaching: self.asked.reaching,
                    input: self.input,
                    chain: self.asked.chain,
                    target_mm: query.target_room_mm,
                    seed: query.seed,
                    obstacles: self.asked.obstacles,
                    placement: closest,
                };
                let found = failed.why();
                self.input.progress.advance(1);
                Some((i, query.target_room_mm, found))
            })
            .collect();
        for (i, point_mm, found) in found {
            match found {
                Found::Why(why) => solved[i].cell.set_why(why),
                Found::Reached(placement) => {
                    solved[i] = self.solved(&grid.cells[i], placement, point_mm);
                }
            }
        }
    }

    /// The placement that reaches the point of `query` from where its
    /// neighbour `last` stood and how it stood, if one does: one descent
    /// of the task's solver; where the neighbour was reached only by the
    /// retry's steering descents (round the body, not through it) and that
    /// descent fails, one of those too.
    fn on_from(
        &self,
        query: &ReachQuery<'_>,
        last: &Placement,
        counts: &dyn Fn(&Placement) -> bool,
        steer: Steer,
    ) -> Option<Placement> {
        let plain = steer != Steer::Only;
        let steering = last.retried || steer != Steer::AsTheNeighbour;
        query.descended_from(
            self.asked.chain,
            last.pose,
            self.asked.reaching.solver.as_ref(),
            &last.solution.q,
            (plain, steering),
            counts,
        )
    }

    /// The neighbour's base moved along the floor as the point moved, and
    /// its posture: along a counter, the same reach again.
    fn carried<'l>(
        &self,
        last: &'l Reached,
        target_room_mm: &Point3<f64>,
    ) -> Option<(BasePose, &'l [f64])> {
        let by_mm = (target_room_mm - last.point_mm).xy();
        let pose = self.prepared.moved(&last.placement.pose, by_mm)?;
        self.prepared
            .admits(&pose, target_room_mm)
            .then_some((pose, last.placement.solution.q.as_slice()))
    }

    /// Grow the reached region from `fresh` (points newly reached, in
    /// order), round after round until a round reaches none: each point
    /// not reached next to a fresh one (in its row or its column) is tried
    /// from each fresh neighbour, where its base stood and then moved as
    /// the point moved. A point is tried from each neighbour once at most,
    /// and every round works from the answers of the round before.
    fn grow(&self, grid: &Grid, solved: &mut [Solved], mut fresh: Vec<usize>, steer: Steer) {
        while !fresh.is_empty() {
            let mut asked: Vec<usize> = fresh
                .iter()
                .flat_map(|&f| neighbours(grid, f).into_iter().flatten())
                .filter(|&i| solved[i].reached.is_none() && !self.settled(i))
                .collect();
            asked.sort_unstable();
            asked.dedup();
            let from = |n: usize| fresh.binary_search(&n).is_ok();
            let filled = self.fill(grid, solved, &asked, from, steer);
            fresh = filled.iter().map(|(i, _)| *i).collect();
            for (i, s) in filled {
                solved[i] = s;
            }
        }
    }

    /// Each point of `asked` (in order) tried from each reached neighbour
    /// that `from` takes: the points reached, in order.
    fn fill(
        &self,
        grid: &Grid,
        solved: &[Solved],
        asked: &[usize],
        from: impl Fn(usize) -> bool + Sync,
        steer: Steer,
    ) -> Vec<(usize, Solved)> {
        asked
            .par_iter()
            .filter_map(|&i| {
                let cell = &grid.cells[i];
                neighbours(grid, i)
                    .into_iter()
                    .flatten()
                    .filter(|&n| from(n))
                    .filter_map(|n| solved[n].reached.as_ref())
                    .find_map(|n| self.hole_from(cell, n, steer))
                    .map(|s| (i, s))
            })
            .collect()
    }

    /// Each point in a gap or at a board's edge searched harder
    /// ([`GridRun::hole_searched`]), and each at the edge through the
    /// person's own body tried from its reached neighbours, steering, in
    /// parallel, and the reached region grown from what that gains; again
    /// while the region's growth opens new ones, each point searched
    /// harder once at most, and tried so once at most.
    fn fill_gaps(&self, grid: &Grid, solved: &mut [Solved]) {
        let mut searched = vec![false; solved.len()];
        let mut steered = vec![false; solved.len()];
        loop {
            let in_gap = gaps(grid, solved);
            let holes: Vec<(usize, bool)> = (0..solved.len())
                .filter(|&i| !self.settled(i))
                .filter_map(|i| {
                    let harder = !searched[i] && (in_gap[i] || at_board_edge(grid, solved, i));
                    let steer = !steered[i] && at_body_edge(grid, solved, i);
                    (harder || steer).then_some((i, harder))
                })
                .collect();
            if holes.is_empty() || self.input.allowance.exhausted() {
                return;
            }
            for &(i, harder) in &holes {
                searched[i] |= harder;
                steered[i] = true;
            }
            let filled: Vec<(usize, Solved)> = holes
                .par_iter()
                .filter_map(|&(i, harder)| {
                    let found = match harder {
                        true => self.hole_searched(grid, solved, i),
                        false => self.tried_from_neighbours(grid, solved, i, Steer::Only),
                    };
                    found.map(|s| (i, s))
                })
                .collect();
            let gained = filled.iter().map(|(i, _)| *i).collect();
            for (i, s) in filled {
                solved[i] = s;
            }
            self.grow(grid, solved, gained, Steer::Always);
        }
    }

    /// Hole `i` tried from each reached neighbour, steering; else searched
    /// again cold [`HARDER`] times, each with another seed and retrying
    /// [`HARDER`] times as many blocked placements.
    fn hole_searched(&self, grid: &Grid, solved: &[Solved], i: usize) -> Option<Solved> {
        let cell = &grid.cells[i];
        let from_neighbour = self.tried_from_neighbours(grid, solved, i, Steer::Always);
        if from_neighbour.is_some() {
            return from_neighbour;
        }
        let solver = self.asked.reaching.solver.as_ref();
        // The searches differ in their seeds: where the solver's own
        // starts draw none, their first searches are one search, made once.
        let descents = RefCell::new(Descents::default());
        (0..HARDER as u64).find_map(|k| {
            let usual = self.query(cell, None);
            let query = ReachQuery {
                seed: usual.seed ^ (0x9e37_79b9_7f4a_7c15_u64.wrapping_mul(k + 1)),
                retry: usual.retry.map(|r| Retry {
                    placements: r.placements * HARDER,
                    ..r
                }),
                descents: Some(&descents),
                ..usual
            };
            let point = self.solved(
                cell,
                self.prepared.reach(&query, solver),
                query.target_room_mm,
            );
            point.reached.is_some().then_some(point)
        })
    }

    /// Point `i` tried from each reached neighbour, as `steer` says.
    fn tried_from_neighbours(
        &self,
        grid: &Grid,
        solved: &[Solved],
        i: usize,
        steer: Steer,
    ) -> Option<Solved> {
        let cell = &grid.cells[i];
        neighbours(grid, i)
            .into_iter()
            .flatten()
            .filter_map(|n| solved[n].reached.as_ref())
            .find_map(|n| self.hole_from(cell, n, steer))
    }

    /// Each point of `wave` not reached whose search was blocked, retried
    /// from its blocked placements as the search would have
    /// (`bases::retry`); the points it reaches, in order. A point still
    /// not reached keeps the first search's answer.
    fn retry_waiting(&self, grid: &Grid, solved: &mut [Solved], wave: usize) -> Vec<usize> {
        let in_wave = |i: usize| (grid.cells[i].row + grid.cells[i].column) % WAVES == wave;
        let waiting: Vec<usize> = (0..solved.len())
            .filter(|&i| in_wave(i) && solved[i].reached.is_none() && !solved[i].blocked.is_empty())
            .collect();
        let gained: Vec<(usize, Solved)> = waiting
            .par_iter()
            .filter_map(|&i| {
                let cell = &grid.cells[i];
                let query = self.query(cell, None);
                let placement = retry(&query, self.asked.chain, &solved[i].blocked)?;
                let point = self.solved(cell, placement, query.target_room_mm);
                point.reached.is_some().then_some((i, point))
            })
            .collect();
        let indices = gained.iter().map(|(i, _)| *i).collect();
        for (i, s) in gained {
            solved[i] = s;
        }
        indices
    }

    /// `cell`'s point tried from `neighbour`: where its base stood (a
    /// plain descent, then the retry's steering one), then moved as the
    /// point moved (with [`Steer::Only`], the steering descent alone);
    /// the answer if one reaches.
    fn hole_from(&self, cell: &GridCell, neighbour: &Reached, steer: Steer) -> Option<Solved> {
        let query = self.query(cell, Some(neighbour));
        let counts = |p: &Placement| (self.judge)(p, cell.point_mm);
        let stayed = &neighbour.placement;
        let on = Some(stayed)
            .filter(|p| self.prepared.admits(&p.pose, &query.target_room_mm))
            .and_then(|p| self.on_from(&query, p, &counts, steer))
            .or_else(|| {
                let (pose, q) = query.last_resort.filter(|_| steer != Steer::Only)?;
                let solver = self.asked.reaching.solver.as_ref();
                let moved = query.solve_from_at(self.asked.chain, pose, solver, q.to_vec());
                counts(&moved).then_some(moved)
            })?;
        Some(self.solved(cell, on, query.target_room_mm))
    }
}

/// Whether each point lies in a gap: a run of points not reached, along a
/// row or a column, with a reached point at either end, at most
/// [`longest_gap`] points long.
fn gaps(grid: &Grid, solved: &[Solved]) -> Vec<bool> {
    let columns = grid.columns.max(1);
    let mut in_gap = vec![false; solved.len()];
    let longest = |a: usize, b: usize| match (grid.cells.get(a), grid.cells.get(b)) {
        (Some(a), Some(b)) => longest_gap(nalgebra::distance(&a.point_mm, &b.point_mm)),
        _ => 1,
    };
    let along_row = longest(0, 1);
    let along_column = longest(0, columns);
    let lines = (0..grid.rows)
        .map(|r| (r * columns, 1, columns, along_row))
        .chain((0..columns).map(|c| (c, columns, grid.rows, along_column)));
    for (first, stride, len, longest) in lines {
        let line: Vec<usize> = (0..len)
            .map(|k| first + k * stride)
            .filter(|&i| i < solved.len())
            .collect();
        mark_gaps(&line, longest, |i| solved[i].reached.is_some(), &mut in_gap);
    }
    in_gap
}

/// The most points a gap may hold where points are `spacing_mm` apart:
/// as many as fit with their reached ends at most [`GAP_SPAN_MM`] apart,
/// and [`GAP_POINTS`] at least.
fn longest_gap(spacing_mm: f64) -> usize {
    let fit = (GAP_SPAN_MM / spacing_mm).floor() - 1.0;
    if fit > GAP_POINTS as f64 {
        fit.min(usize::MAX as f64) as usize
    } else {
        GAP_POINTS
    }
}

/// Whether point `i` is not reached, has a reached neighbour, and came
/// within the tolerance only through an obstacle or a side of the room:
/// at the edge of the reached region, against a board that a search blind
/// to the room may have gone through rather than round. (Through the
/// person's own body instead, the body is most often what ends the reach:
/// on the 100,000-point map of `bench_scale` searching those harder too
/// costs 4 s for 4 points more.)
fn at_board_edge(grid: &Grid, solved: &[Solved], i: usize) -> bool {
    matches!(
        solved[i].through,
        Some(Blocker::Obstacle(_) | Blocker::Wall(_))
    ) && at_edge(grid, solved, i)
}

/// Whether point `i` is not reached, has a reached neighbour, and came
/// within the tolerance through the person's own body or base (a thigh,
/// the backrest): at the edge of the reached region, where the body most
/// often ends the reach, but a descent from the neighbour's posture that
/// steers round the body may not (one steering descent a neighbour, not a
/// search four times harder: that costs 4 s for 4 points on the
/// 100,000-point map of `bench_scale`; these descents 0.04 s for its 512
/// such points, 77 points more on 160 random maps).
fn at_body_edge(grid: &Grid, solved: &[Solved], i: usize) -> bool {
    matches!(
        solved[i].through,
        Some(Blocker::Own(_) | Blocker::Body(_) | Blocker::Balance(_))
    ) && at_edge(grid, solved, i)
}

/// Whether point `i` is not reached and has a reached neighbour, in its
/// row or its column.
fn at_edge(grid: &Grid, solved: &[Solved], i: usize) -> bool {
    let reached = |n: Option<usize>| n.is_some_and(|n| solved[n].reached.is_some());
    solved[i].reached.is_none() && neighbours(grid, i).into_iter().any(reached)
}

/// Marks in `in_gap` the points of `line` (indices, in order) that lie
/// between two reached ones with none reached between, at most `longest`
/// of them.
fn mark_gaps(line: &[usize], longest: usize, reached: impl Fn(usize) -> bool, in_gap: &mut [bool]) {
    let mut last_reached: Option<usize> = None;
    for (k, &i) in line.iter().enumerate() {
        if !reached(i) {
            continue;
        }
        if let Some(j) = last_reached.filter(|&j| k - j - 1 <= longest) {
            for &g in &line[j + 1..k] {
                in_gap[g] = true;
            }
        }
        last_reached = Some(k);
    }
}

/// When a point tried from its neighbour's posture takes a steering
/// descent (the retry's solver, which keeps a clear posture clear) after
/// the plain descent fails.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Steer {
    /// Only where the neighbour was itself reached by one.
    AsTheNeighbour,
    /// Always (a point at the edge of the reached region).
    Always,
    /// Only the steering descent, the plain ones made already (a point at
    /// the edge of the reached region through the person's own body).
    Only,
}

/// The indices of point `i`'s neighbours in `grid`: left and right in its
/// row, below and above in its column.
fn neighbours(grid: &Grid, i: usize) -> [Option<usize>; 4] {
    let columns = grid.columns.max(1);
    let (row, column) = (i / columns, i % columns);
    let at = |r: Option<usize>, c: Option<usize>| {
        let (r, c) = (r?, c?);
        (r < grid.rows && c < columns).then_some(r * columns + c)
    };
    [
        at(Some(row), column.checked_sub(1)),
        at(Some(row), Some(column + 1)),
        at(row.checked_sub(1), Some(column)),
        at(Some(row + 1), Some(column)),
    ]
}

#[cfg(test)]
mod tests {
    use super::{longest_gap, mark_gaps};

    /// The gaps of a line written as `#` (reached) and `.` (not).
    fn gaps_of(line: &str, longest: usize) -> Vec<usize> {
        let reached: Vec<bool> = line.chars().map(|c| c == '#').collect();
        let indices: Vec<usize> = (0..reached.len()).collect();
        let mut in_gap = vec![false; reached.len()];
        mark_gaps(&indices, longest, |i| reached[i], &mut in_gap);
        (0..reached.len()).filter(|&i| in_gap[i]).collect()
    }

    #[test]
    fn a_gap_is_a_run_not_reached_with_a_reached_point_at_either_end() {
        let table: [(&str, usize, &[usize]); 10] = [
            ("#.#", 4, &[1]),
            ("#.#", 1, &[1]),
            ("#....#", 4, &[1, 2, 3, 4]),
            ("#....#", 3, &[]),
            ("#..#.#..", 1, &[4]),
            ("#..#.#..", 2, &[1, 2, 4]),
            ("..#..", 4, &[]),
            ("####", 4, &[]),
            ("....", 4, &[]),
            ("", 4, &[]),
        ];
        for (line, longest, expected) in table {
            assert_eq!(gaps_of(line, longest), expected, "{line:?} {longest}");
        }
    }

    #[test]
    fn a_gap_spans_at_most_150_mm_between_its_reached_ends_or_three_points() {
        let table = [
            (10.0, 14),
            (20.9, 6),
            (37.5, 3),
            (50.0, 3),
            (200.0, 3),
            (0.0, usize::MAX),
        ];
        for (spacing_mm, longest) in table {
            assert_eq!(longest_gap(spacing_mm), longest, "{spacing_mm} mm");
        }
    }
}
