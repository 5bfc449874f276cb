//! Mutated scenarios: the examples and the malformed files of tests/errors,
//! cut, spliced and sprinkled with tokens, go through parse, check and
//! diagnostic rendering, and those that check are run, every task, within
//! a bound on solver starts that keeps each case short. Nothing may panic,
//! and every
//! diagnostic's span must lie inside the text it points into.

use proptest::prelude::*;
use reach::plugin::Registry;
use reach::{Input, Limits};

/// The seed files, the examples first; returns them and how many examples.
fn seeds() -> (Vec<Vec<u8>>, usize) {
    let mut files: Vec<_> = ["examples", "tests/errors"]
        .iter()
        .flat_map(|d| std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path()))
        .filter(|p| p.extension().is_some_and(|e| e == "reach"))
        .collect();
    files.sort();
    let examples = files.iter().filter(|p| p.starts_with("examples")).count();
    let mut seeds = vec![SMALL_MAPS.as_bytes().to_vec()];
    seeds.extend(files.iter().map(|p| std::fs::read(p).unwrap()));
    (seeds, examples + 1)
}

/// A seed whose maps and gaze map fit within the cases' bound on solver
/// starts (the examples' maps do not), so that mutated maps run too.
const SMALL_MAPS: &str = "units mm deg
use std::arm
use std::body
room r {
  size 3000 x 3000 x 2500
  box shelf at (0, 1000, 1200) size (300, 600, 20)
  box lip at (280, 1000, 1220) size (20, 600, 60)
  target jar at (150, 1300, 1300)
}
person p {
  mannequin upper_body
  base fixed { at (700, 1300, 930) heading 180deg }
}
person q {
  mannequin right_arm
  base fixed { at (700, 1300, 930) heading 180deg }
}
map shelf.top by q { step 150mm solver incremental { starts 2 } blocked_retries 1 blocked_solver incremental { starts 8 } }
gaze_map shelf.top by p { step 200mm solver fabrik { starts 1 } }
gaze jar by p
reach jar by q { solver dls }
";

const TOKENS: &[&str] = &[
    "(",
    ")",
    "{",
    "}",
    ",",
    "-",
    "+",
    "*",
    "/",
    "1e308",
    "0",
    "1e15",
    "deg",
    "mm",
    "let",
    "room",
    "reach",
    "map",
    "by",
    "\"",
    "\n",
    "use std::arm",
    "use std::paper",
    "nan",
    "0.0000001",
    "limits",
    "x",
    "99999999999999999999",
    "surface",
    "base wheelchair",
    "base trolley",
    "step 1mm",
    "top",
    ".",
    "//",
    "/*",
];

#[derive(Clone, Debug)]
enum Edit {
    Insert {
        at: f64,
        token: usize,
    },
    Delete {
        at: f64,
        len: usize,
    },
    Splice {
        at: f64,
        from_seed: usize,
        from: f64,
        len: usize,
    },
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (0.0..1.0f64, 0..TOKENS.len()).prop_map(|(at, token)| Edit::Insert { at, token }),
        (0.0..1.0f64, 1usize..12).prop_map(|(at, len)| Edit::Delete { at, len }),
        (0.0..1.0f64, any::<usize>(), 0.0..1.0f64, 1usize..60).prop_map(
            |(at, from_seed, from, len)| Edit::Splice {
                at,
                from_seed,
                from,
                len
            }
        ),
    ]
}

fn apply(seeds: &[Vec<u8>], base: usize, edits: &[Edit]) -> String {
    let mut s = seeds[base % seeds.len()].clone();
    let pos = |f: f64, len: usize| ((f * len as f64) as usize).min(len);
    for e in edits {
        match *e {
            Edit::Insert { at, token } => {
                let i = pos(at, s.len());
                s.splice(i..i, TOKENS[token].bytes());
            }
            Edit::Delete { at, len } => {
                let i = pos(at, s.len());
                s.drain(i..(i + len).min(s.len()));
            }
            Edit::Splice {
                at,
                from_seed,
                from,
                len,
            } => {
                let other = &seeds[from_seed % seeds.len()];
                let a = pos(from, other.len());
                let piece: Vec<u8> = other[a..(a + len).min(other.len())].to_vec();
                let i = pos(at, s.len());
                s.splice(i..i, piece);
            }
        }
    }
    String::from_utf8_lossy(&s).into_owned()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn mutated_scenarios_never_panic(
        from_example in any::<bool>(),
        base in any::<usize>(),
        edits in prop::collection::vec(edit(), 1..5),
    ) {
        // Half the cases start from an example, so that many still check and run.
        let (seeds, examples) = seeds();
        let base = if from_example { base % examples } else { base };
        let text = apply(&seeds, base, &edits);
        let registry = Registry::builtin();
        // A small bound on solver starts keeps every case short, maps and
        // gazes included; beyond it a case is refused, which is tested too.
        let limits = Limits { solver_starts: 2_000, ..Limits::default() };
        let input = Input::Text { name: "mutated.reach", text: &text };
        let (sources, checked) = reach::check_within(input, &registry, &limits);
        match checked {
            Err(diagnostics) => {
                for e in &diagnostics.errors {
                    if let Some(span) = e.span() {
                        let len = sources.get(span.file).text.len();
                        prop_assert!(span.start <= span.end && span.end as usize <= len, "{:?} outside {len} bytes", span);
                    }
                }
                prop_assert!(!diagnostics.render(true).is_empty());
            }
            Ok(scenario) => {
                let report = reach::run(&scenario);
                prop_assert_eq!(report.tasks.len(), scenario.tasks.len());
            }
        }
    }
}
