//! `reach run --shard K/N` and `reach merge`: a study split across the
//! machines of a batch scheduler (a Slurm job array, a Kubernetes Indexed
//! Job), each running one shard of every population's people, and joined
//! into the report one run gives (`scenario/shard.rs`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use reach::plugin::Registry;
use reach::progress::Progress;
use reach::{fingerprint, read_shard, write_shard, PeopleBuilt, ShardOf, ShardPart};
use reach::{Diagnostics, Error, ErrorKind, Input, Limits, Scenario, Sources};

/// What a command reads a scenario with.
pub struct Reading<'a> {
    pub file: &'a Path,
    pub limits: Limits,
    pub allowed: &'a [PathBuf],
}

/// `reach run FILE --shard K/N`: the shard's file, to print.
pub fn shard_file(
    registry: &Registry,
    reading: &Reading<'_>,
    shard: ShardOf,
    progress: &dyn Progress,
) -> Result<String, Diagnostics> {
    let session = reach::Session::default()
        .limits(reading.limits)
        .allowing(reading.allowed)
        .building(PeopleBuilt::Shard(shard));
    let (sources, checked) = session.check(Input::Path(reading.file), registry);
    let scenario = checked?;
    let parts = (session.progress(progress).run_shard(&scenario, shard))
        .map_err(|error| Diagnostics::single(error).attach(&sources))?;
    let ours = fingerprint(&sources, reading.limits.file_bytes);
    Ok(write_shard(shard, &ours, &parts))
}

/// A scenario run by shards and merged: the report one run gives.
pub struct Merged {
    pub scenario: Scenario,
    pub sources: Sources,
    pub report: reach::report::Report,
}

/// `reach merge FILE SHARD...`: FILE's report as one run gives it, from
/// the shards' files at `shards`.
pub fn merged(
    registry: &Registry,
    reading: &Reading<'_>,
    shards: &[PathBuf],
    progress: &dyn Progress,
) -> Result<Merged, Diagnostics> {
    let session = reach::Session::default()
        .limits(reading.limits)
        .allowing(reading.allowed)
        .building(PeopleBuilt::First);
    let (sources, checked) = session.check(Input::Path(reading.file), registry);
    let scenario = checked?;
    let ours = fingerprint(&sources, reading.limits.file_bytes);
    let limit_bytes = reading.limits.file_bytes;
    let parts = gather(&scenario, &ours, shards, (reading.file, limit_bytes))
        .map_err(Diagnostics::single)?;
    let ran = (session.progress(progress).run_merged(&scenario, &parts))
        .map_err(|error| Diagnostics::single(error).attach(&sources))?;
    Ok(Merged {
        scenario,
        sources,
        report: ran.report,
    })
}

/// Every shard's parts, in the order of the shards (so each population's
/// people in draw order), once each shard is known to be of this scenario
/// (`ours`, its fingerprint), of the same count, given once, whole.
fn gather(
    scenario: &Scenario,
    ours: &str,
    paths: &[PathBuf],
    (file, limit_bytes): (&Path, u64),
) -> Result<Vec<ShardPart>, Error> {
    let mut by_index: BTreeMap<usize, (PathBuf, Vec<ShardPart>)> = BTreeMap::new();
    let mut count = None;
    for path in paths {
        let bad = |why: String| {
            Error::unplaced(ErrorKind::BadShard {
                path: path.display().to_string(),
                why,
            })
        };
        let bytes = reach::read_root(path, limit_bytes).map_err(|e| bad(e.to_string()))?;
        let text = String::from_utf8(bytes).map_err(|_| bad("it is not UTF-8 text".into()))?;
        let (shard, theirs, parts) = read_shard(&text).map_err(bad)?;
        if theirs != ours {
            return Err(bad(
                "it was run on other scenario files than these (or by another version of reach)"
                    .into(),
            ));
        }
        match count {
            Some(n) if n != shard.count => {
                return Err(bad(format!(
                    "it is shard {} of {}, the first given of {n}",
                    shard.index, shard.count
                )))
            }
            _ => count = Some(shard.count),
        }
        whole(scenario, shard, &parts).map_err(bad)?;
        if let Some((other, _)) = by_index.get(&shard.index) {
            let why = format!(
                "it is shard {}/{}, as `{}` is",
                shard.index,
                shard.count,
                other.display()
            );
            return Err(bad(why));
        }
        by_index.insert(shard.index, (path.clone(), parts));
    }
    if let Some(words) = ShardOf::missing(count.unwrap_or(0), |k| by_index.contains_key(&k)) {
        return Err(Error::unplaced(ErrorKind::BadShard {
            path: file.display().to_string(),
            why: format!("{words} (of its run)"),
        }));
    }
    Ok(by_index
        .into_values()
        .flat_map(|(_, parts)| parts)
        .collect())
}

/// Whether `parts` are shard `shard`'s whole part of `scenario`'s run:
/// one part for each task by a population, of the shard's people, an
/// outcome each, a map's points as many as its frame's.
fn whole(scenario: &Scenario, shard: ShardOf, parts: &[ShardPart]) -> Result<(), String> {
    let asked: Vec<usize> = (scenario.tasks.iter().enumerate())
        .filter(|(_, t)| t.population.is_some())
        .map(|(k, _)| k)
        .collect();
    let given: Vec<usize> = parts.iter().map(|p| p.task).collect();
    if asked != given {
        return Err(format!(
            "its tasks by populations are {given:?}, the scenario's {asked:?}"
        ));
    }
    for part in parts {
        let task = &scenario.tasks[part.task];
        let population = &scenario.populations[task.population.expect("a population's task")];
        let people = shard.people(population.len());
        if part.people != people || part.outcomes.len() != people.len() {
            return Err(format!(
                "its people of `{}` are {:?} ({} answers), shard {}/{}'s are {people:?}",
                population.name,
                part.people,
                part.outcomes.len(),
                shard.index,
                shard.count
            ));
        }
        let points = part.frame.as_ref().map(|f| f.cells.len());
        for outcome in &part.outcomes {
            if let Some(reached) = &outcome.reached {
                if Some(reached.len()) != points {
                    return Err(format!(
                        "a map's points reached are {}, its frame has {points:?}",
                        reached.len()
                    ));
                }
            }
        }
    }
    Ok(())
}
