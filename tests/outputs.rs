//! Hostile names through every output: names from a URDF (its joints and
//! links, which reach why causes and map tooltips) and the scenario's own
//! file name, made of markup, quotes, separators, line breaks, controls
//! and bidirectional overrides, go through every file an `--out` set
//! writes. Each file stays what it claims to be: the SVGs well-formed XML
//! with no element a name made, the page's scripts as many as the page
//! has, the CSVs with one field per column on every row, the JSON (and the
//! glTF's) parseable, the text free of anything that moves the cursor or
//! reorders what is shown.

use std::path::Path;

use proptest::prelude::*;
use reach::plugin::Registry;
use reach::Input;

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

/// `text` as XML character references (what a URDF's attribute holds).
fn xml_refs(text: &str) -> String {
    text.chars()
        .map(|c| format!("&#x{:x};", u32::from(c)))
        .collect()
}

/// A file name made of `name`: no `/`, no NUL, not too long.
fn file_name(name: &str) -> String {
    let plain: String = name.chars().filter(|&c| c != '/' && c != '\0').collect();
    let short: String = plain.chars().take(60).collect();
    format!("{short}.reach")
}

/// The files of an `--out` set of a URDF arm whose elbow joint is named
/// `joint` and whose forearm link `link`, in a scenario file named `file`:
/// a reach it makes, one it does not (with why), and a map with why.
fn output_files(joint: &str, link: &str, file: &str) -> Vec<(String, Vec<u8>)> {
    let dir = tempfile::tempdir().unwrap();
    let urdf = std::fs::read_to_string("tests/data/human_arm.urdf").unwrap();
    let urdf = urdf
        .replace(
            "name=\"elbow_flexion\"",
            &format!("name=\"{}\"", xml_refs(joint)),
        )
        .replace("\"forearm\"", &format!("\"{}\"", xml_refs(link)));
    std::fs::write(dir.path().join("arm.urdf"), urdf).unwrap();
    let path = dir.path().join(file);
    std::fs::write(
        &path,
        "units mm\nmannequin arm from urdf \"arm.urdf\" root \"pelvis\" tip \"grip\"\n\
         room r {\n  size 3000 x 3000 x 2500\n  box shelf at (0, 1100, 1200) size (300, 800, 20)\n  \
         target cup at (1300, 1300, 1200)\n  target far at (2900, 1500, 2400)\n}\n\
         person p { mannequin arm base fixed { at (900, 1500, 930) heading 180deg } }\n\
         reach cup, far by p\n\
         map shelf.top by p { step 200mm why true solver incremental { starts 2 } blocked_retries 0 }\n",
    )
    .unwrap();
    let registry = Registry::builtin();
    let (_, checked) = reach::check(Input::Path(&path), &registry);
    let scenario = checked.unwrap_or_else(|d| panic!("{}", d.render(false)));
    let report = reach::run(&scenario).unwrap();
    reach::output::output_set(&report, &scenario, registry.formats())
}

/// How many records of `csv` have each number of fields (RFC 4180:
/// fields quoted with `"`, a quote doubled inside).
fn field_counts(csv: &str) -> Vec<usize> {
    let (mut counts, mut fields, mut quoted, mut chars) = (Vec::new(), 1, false, csv.chars());
    let mut at_start = true;
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', false) => quoted = true,
            ('"', true) => {
                // A doubled quote stays inside; else the field's quote ends.
                let rest = chars.as_str();
                if rest.starts_with('"') {
                    chars.next();
                } else {
                    quoted = false;
                }
            }
            (',', false) => fields += 1,
            ('\n', false) => {
                counts.push(fields);
                fields = 1;
                at_start = true;
                continue;
            }
            _ => {}
        }
        at_start = false;
    }
    if !at_start {
        counts.push(fields);
    }
    counts
}

/// Whether `svg` is well-formed XML with no `script` element and no
/// element or attribute outside SVG's usual ones that a name could make.
fn well_formed_svg(svg: &str) -> Result<(), String> {
    let parser = xml::reader::EventReader::new(svg.as_bytes());
    for event in parser {
        match event.map_err(|e| e.to_string())? {
            xml::reader::XmlEvent::StartElement {
                name, attributes, ..
            } => {
                if name.local_name.eq_ignore_ascii_case("script") {
                    return Err("a script element".into());
                }
                if let Some(a) = attributes
                    .iter()
                    .find(|a| a.name.local_name.starts_with("on"))
                {
                    return Err(format!("an event attribute {}", a.name.local_name));
                }
            }
            _ => continue,
        }
    }
    Ok(())
}

/// The JSON chunk of a GLB.
fn glb_json(glb: &[u8]) -> &[u8] {
    let length = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    &glb[20..20 + length]
}

fn check_files(files: &[(String, Vec<u8>)], scripts: usize) -> Result<(), TestCaseError> {
    for (name, bytes) in files {
        let text = String::from_utf8_lossy(bytes);
        let ext = Path::new(name).extension().and_then(|e| e.to_str());
        match ext {
            Some("json") => {
                let parsed = serde_json::from_slice::<serde_json::Value>(bytes);
                prop_assert!(parsed.is_ok(), "{name}: {parsed:?}");
            }
            Some("glb") => {
                let parsed = serde_json::from_slice::<serde_json::Value>(glb_json(bytes));
                prop_assert!(parsed.is_ok(), "{name}'s JSON: {parsed:?}");
            }
            Some("svg") => {
                let checked = well_formed_svg(&text);
                prop_assert!(checked.is_ok(), "{name}: {checked:?}");
            }
            Some("html") => {
                let opened = text.matches("<script").count();
                let closed = text.matches("</script").count();
                prop_assert_eq!((opened, closed), (scripts, scripts), "{}", name);
            }
            Some("csv") => {
                let counts = field_counts(&text);
                prop_assert!(counts.iter().all(|&n| n == counts[0]), "{name}: {counts:?}");
            }
            Some("txt") => {
                for line in text.lines() {
                    prop_assert_eq!(&*reach::escaped(line), line, "{}", name);
                }
            }
            _ => {}
        }
    }
    Ok(())
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
