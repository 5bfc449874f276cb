//! The file a shard of a run writes (`reach run --shard K/N`, JSON) and
//! the merge reads back: which shard of how many, a fingerprint of the
//! scenario it ran (its files' text and the data files they name, with
//! the tool's version), and of each task by a population, how each of the
//! shard's people ended. Numbers that the merged report prints (a map's
//! corner, its points) are kept as Rust writes them and read back exactly.

use std::ops::Range;

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

use super::shard::{ShardOf, ShardPart};
use crate::report::{MapFrame, MemberOutcome, ShareCell, ShareGrid};
use crate::source::Sources;

/// What the first field of a shard file says.
const FORMAT: &str = "reach shard";

/// The version of this file's layout.
const VERSION: u32 = 1;

/// A shard's file, as JSON.
#[derive(Serialize, Deserialize)]
struct FileJson {
    format: String,
    version: u32,
    /// `K/N`.
    shard: String,
    /// The scenario's fingerprint ([`fingerprint`]).
    scenario: String,
    parts: Vec<PartJson>,
}

#[derive(Serialize, Deserialize)]
struct PartJson {
    task: usize,
    people: [usize; 2],
    #[serde(skip_serializing_if = "Option::is_none", default)]
    frame: Option<FrameJson>,
    outcomes: Vec<OutcomeJson>,
}

#[derive(Serialize, Deserialize)]
struct OutcomeJson {
    task: String,
    ok: bool,
    not_placed: bool,
    verdict: String,
    /// For a map: `1` for each point reached, `0` for each not.
    #[serde(skip_serializing_if = "Option::is_none", default)]
    reached: Option<String>,
}

/// A map's frame; numbers as Rust writes them.
#[derive(Serialize, Deserialize)]
struct FrameJson {
    of: String,
    base: String,
    view: String,
    step_mm: String,
    corner_mm: [String; 3],
    u_mm: [String; 3],
    v_mm: [String; 3],
    columns: usize,
    rows: usize,
    seen_from: [String; 3],
    /// Each point: column, row, and its three coordinates.
    cells: Vec<(usize, usize, [String; 3])>,
}

/// The fingerprint of the scenario whose files are `sources`: the tool's
/// version, each file's text and each data file's bytes (as far as they
/// can be read within `limit_bytes`), hashed.
pub fn fingerprint(sources: &Sources, limit_bytes: u64) -> String {
    let mut hash = Sha256::new();
    let mut add = |bytes: &[u8]| {
        hash.update((bytes.len() as u64).to_le_bytes());
        hash.update(bytes);
    };
    add(env!("CARGO_PKG_VERSION").as_bytes());
    for (_, file) in sources.iter() {
        add(file.text.as_bytes());
    }
    for path in sources.data_paths() {
        match crate::read::read_root(path, limit_bytes) {
            Ok(bytes) => add(&bytes),
            Err(_) => add(b"unreadable"),
        }
    }
    format!("{:x}", hash.finalize())
}

/// The file of shard `shard` of a run of the scenario of fingerprint
/// `scenario`, which found `parts`.
pub fn write_shard(shard: ShardOf, scenario: &str, parts: &[ShardPart]) -> String {
    let file = FileJson {
        format: FORMAT.into(),
        version: VERSION,
        shard: format!("{}/{}", shard.index, shard.count),
        scenario: scenario.into(),
        parts: parts.iter().map(part_json).collect(),
    };
    let mut text = serde_json::to_string(&file).expect("a shard serialises");
    text.push('\n');
    text
}

fn part_json(part: &ShardPart) -> PartJson {
    PartJson {
        task: part.task,
        people: [part.people.start, part.people.end],
        frame: part.frame.as_ref().map(frame_json),
        outcomes: (part.outcomes.iter())
            .map(|o| OutcomeJson {
                task: o.task.into(),
                ok: o.ok,
                not_placed: o.not_placed,
                verdict: o.verdict.clone(),
                reached: (o.reached.as_ref())
                    .map(|r| r.iter().map(|&b| if b { '1' } else { '0' }).collect()),
            })
            .collect(),
    }
}

fn frame_json(frame: &MapFrame) -> FrameJson {
    let g = &frame.grid;
    let three = |v: [f64; 3]| v.map(|x| x.to_string());
    FrameJson {
        of: g.of.into(),
        base: g.base.clone(),
        view: g.view.into(),
        step_mm: g.step_mm.to_string(),
        corner_mm: three(g.corner_mm),
        u_mm: three(g.u_mm),
        v_mm: three(g.v_mm),
        columns: g.columns,
        rows: g.rows,
        seen_from: three(g.seen_from),
        cells: (frame.cells.iter())
            .map(|c| (c.column, c.row, three(c.point_mm)))
            .collect(),
    }
}

/// A shard's file read back: which shard, the fingerprint of its
/// scenario, and its parts; or why it is not a shard file this tool
/// wrote.
pub fn read_shard(text: &str) -> Result<(ShardOf, String, Vec<ShardPart>), String> {
    let file: FileJson =
        serde_json::from_str(text).map_err(|e| format!("not a shard file of reach: {e}"))?;
    if file.format != FORMAT {
        return Err(format!("its format is `{}`, not `{FORMAT}`", file.format));
    }
    if file.version != VERSION {
        return Err(format!(
            "its version is {}, this tool reads {VERSION}",
            file.version
        ));
    }
    let shard = ShardOf::parse(&file.shard)?;
    let parts = (file.parts.into_iter())
        .map(part_of)
        .collect::<Result<Vec<_>, String>>()?;
    Ok((shard, file.scenario, parts))
}

fn part_of(part: PartJson) -> Result<ShardPart, String> {
    let [start, end] = part.people;
    let people: Range<usize> = start..end;
    let frame = part.frame.map(frame_of).transpose()?;
    let outcomes = (part.outcomes.into_iter())
        .map(|o| {
            let reached = o.reached.map(|r| bits(&r)).transpose()?;
            Ok(MemberOutcome {
                task: known(
                    &o.task,
                    &["reach", "gaze", "map", "gaze_map", "reach+gaze", "task"],
                )?,
                ok: o.ok,
                not_placed: o.not_placed,
                verdict: o.verdict,
                reached,
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(ShardPart {
        task: part.task,
        people,
        outcomes,
        frame,
    })
}

fn frame_of(f: FrameJson) -> Result<MapFrame, String> {
    let grid = ShareGrid {
        of: known(&f.of, &["reach", "gaze"])?,
        base: f.base,
        view: known(&f.view, &["plan", "elevation"])?,
        step_mm: number(&f.step_mm)?,
        corner_mm: numbers(&f.corner_mm)?,
        u_mm: numbers(&f.u_mm)?,
        v_mm: numbers(&f.v_mm)?,
        columns: f.columns,
        rows: f.rows,
        seen_from: numbers(&f.seen_from)?,
    };
    let cells = (f.cells.iter())
        .map(|(column, row, point)| {
            Ok(ShareCell {
                column: *column,
                row: *row,
                point_mm: numbers(point)?,
                share: 0.0,
                reached: 0,
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(MapFrame { grid, cells })
}

/// `word` as one of `words` (the names this tool writes).
fn known(word: &str, words: &[&'static str]) -> Result<&'static str, String> {
    (words.iter().copied())
        .find(|w| *w == word)
        .ok_or_else(|| format!("`{word}` is not one of {}", words.join(", ")))
}

fn number(text: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .map_err(|_| format!("`{text}` is not a number"))
}

fn numbers(texts: &[String; 3]) -> Result<[f64; 3], String> {
    Ok([number(&texts[0])?, number(&texts[1])?, number(&texts[2])?])
}

fn bits(text: &str) -> Result<Vec<bool>, String> {
    (text.chars())
        .map(|c| match c {
            '0' => Ok(false),
            '1' => Ok(true),
            _ => Err(format!("`{c}` in a map's points reached (0 or 1 each)")),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shard_reads_back_as_written_to_the_last_bit() {
        let grid = ShareGrid {
            of: "reach",
            base: "manual_wheelchair".into(),
            view: "plan",
            step_mm: 100.0,
            corner_mm: [0.1 + 0.2, 1e-300, -2.5],
            u_mm: [1.0 / 3.0, 0.0, 0.0],
            v_mm: [0.0, 600.0, 0.0],
            columns: 2,
            rows: 1,
            seen_from: [0.0, 0.0, 1.0],
        };
        let cell = |column| ShareCell {
            column,
            row: 0,
            point_mm: [f64::MIN_POSITIVE, 2.0 / 7.0, 1070.0],
            share: 0.0,
            reached: 0,
        };
        let part = ShardPart {
            task: 3,
            people: 10..12,
            outcomes: vec![
                MemberOutcome {
                    task: "map",
                    ok: true,
                    not_placed: false,
                    verdict: "1 of 2 points \"reached\"".into(),
                    reached: Some(vec![true, false]),
                },
                MemberOutcome {
                    task: "map",
                    ok: false,
                    not_placed: true,
                    verdict: "does NOT fit".into(),
                    reached: None,
                },
            ],
            frame: Some(MapFrame {
                grid,
                cells: vec![cell(0), cell(1)],
            }),
        };
        let shard = ShardOf { index: 2, count: 5 };
        let text = write_shard(shard, "abc", std::slice::from_ref(&part));
        assert_eq!(
            read_shard(&text),
            Ok((shard, "abc".to_string(), vec![part]))
        );
    }

    #[test]
    fn a_file_not_written_as_a_shard_is_refused_with_why() {
        let table = [
            ("{}", "not a shard file"),
            (
                r#"{"format":"x","version":1,"shard":"1/1","scenario":"","parts":[]}"#,
                "format is `x`",
            ),
            (
                r#"{"format":"reach shard","version":9,"shard":"1/1","scenario":"","parts":[]}"#,
                "version is 9",
            ),
            (
                r#"{"format":"reach shard","version":1,"shard":"2/1","scenario":"","parts":[]}"#,
                "K must be",
            ),
        ];
        for (text, why) in table {
            let error = read_shard(text).expect_err(text);
            assert!(error.contains(why), "{text}: {error}");
        }
    }
}
