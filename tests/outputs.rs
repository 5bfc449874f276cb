//! Hostile names through every output: names from a URDF (its joints and
//! links, which reach why causes and map tooltips) and the scenario's own
//! file name, made of markup, quotes, separators, line breaks, controls
//! and bidirectional overrides, go through every file an `--out` set
//! writes. Each file stays what it claims to be: the SVGs well-formed XML
//! with no element a name made, the page's scripts as many as the page
//! has, the CSVs with one field per column on every row, the JSON (and the
//! glTF's) parseable, the text free of anything that moves the cursor or
//! reorders what is shown.

use proptest::prelude::*;

use crate::output_checks::{field_counts, file_problem, well_formed_svg};

/// Pieces hostile names are made of.
const PIECES: [&str; 18] = [
    "<",
    ">",
    "&",
    "\"",
    "'",
    ",",
    ";",
    "\n",
    "\t",
    "\u{202e}",
    "\u{9b}",
    "\u{2028}",
    "</title><script>alert(1)</script>",
    "]]>",
    "<!--",
    "&amp;",
    "é",
    "elbow",
];

fn hostile_name() -> impl Strategy<Value = String> {
    prop::collection::vec(prop::sample::select(PIECES.to_vec()), 1..6).prop_map(|p| p.concat())
}

/// A file name made of `name`: no `/`, no NUL, not too long.
fn file_name(name: &str) -> String {
    let plain: String = name.chars().filter(|&c| c != '/' && c != '\0').collect();
    let short: String = plain.chars().take(60).collect();
    format!("{short}.reach")
}

fn check_files(files: &[(String, Vec<u8>)], scripts: usize) -> Result<(), TestCaseError> {
    for (name, bytes) in files {
        let problem = file_problem(name, bytes, scripts);
        prop_assert!(problem.is_none(), "{}", problem.unwrap_or_default());
    }
    Ok(())
}

/// The files of an `--out` set of a URDF arm whose elbow joint is named
/// `joint` and whose forearm link `link`, in a scenario file named `file`.
fn output_files(joint: &str, link: &str, file: &str) -> Vec<(String, Vec<u8>)> {
    let urdf = std::fs::read_to_string("tests/data/human_arm.urdf").unwrap();
    crate::output_checks::output_files(&urdf, joint, link, file).unwrap_or_else(|e| panic!("{e}"))
}

/// The page's `<script` tags with plain names.
fn scripts_of_a_plain_page() -> usize {
    let files = output_files("elbow_flexion", "forearm", "plain.reach");
    let (_, page) = files.iter().find(|(n, _)| n == "report.html").unwrap();
    String::from_utf8_lossy(page).matches("<script").count()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn hostile_names_leave_every_output_what_it_claims_to_be(
        joint in hostile_name(),
        link in hostile_name(),
        file in hostile_name(),
    ) {
        let files = output_files(&joint, &link, &file_name(&file));
        check_files(&files, scripts_of_a_plain_page())?;
    }
}

/// The checks can fail: markup written raw into an SVG, a row with a
/// comma unquoted, a script tag in the page, a control in the text.
#[test]
fn the_checks_of_each_output_catch_what_they_look_for() {
    assert!(well_formed_svg("<svg><title>a</title><script>x</script></svg>").is_err());
    assert!(well_formed_svg("<svg><title>a<b</title></svg>").is_err());
    assert!(well_formed_svg("<svg><title>a &lt;b</title></svg>").is_ok());
    assert_eq!(field_counts("a,b\n\"x,y\",z\n"), [2, 2]);
    assert_eq!(field_counts("a,b\nx,y,z\n"), [2, 3]);
    assert_eq!(field_counts("a,b\n\"x\"\"\ny\",z\n"), [2, 2]);
    let page = vec![("report.html".to_string(), b"<script></script>".to_vec())];
    assert!(check_files(&page, 0).is_err());
    let text = vec![("report.txt".to_string(), "a\u{202e}b\n".as_bytes().to_vec())];
    assert!(check_files(&text, 0).is_err());
}
