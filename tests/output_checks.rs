//! The checks of tests/outputs.rs, shared with the fuzz target
//! `outputs` (`fuzz/fuzz_targets/outputs.rs` includes this file): an
//! `--out` set of a scene whose names are given, and whether each file of
//! it is what it claims to be.

use std::path::Path;

use reach::plugin::Registry;
use reach::Input;

/// `text` as XML character references (what a URDF's attribute holds).
pub fn xml_refs(text: &str) -> String {
    text.chars()
        .map(|c| format!("&#x{:x};", u32::from(c)))
        .collect()
}

/// The files of an `--out` set of a URDF arm (`urdf`, the text of
/// tests/data/human_arm.urdf) whose elbow joint is named `joint` and whose
/// forearm link `link`, in a scenario file named `file`: a reach it makes,
/// one it does not (with why), and a map with why; the diagnostics where
/// the names do not make a scene (a URDF that refuses them).
pub fn output_files(
    urdf: &str,
    joint: &str,
    link: &str,
    file: &str,
) -> Result<Vec<(String, Vec<u8>)>, String> {
    let dir = tempfile::tempdir().unwrap();
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
    let scenario = checked.map_err(|d| d.render(false))?;
    let report = reach::run(&scenario).unwrap();
    Ok(reach::output::output_set(
        &report,
        &scenario,
        registry.formats(),
    ))
}

/// How many records of `csv` have each number of fields (RFC 4180:
/// fields quoted with `"`, a quote doubled inside).
pub fn field_counts(csv: &str) -> Vec<usize> {
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
pub fn well_formed_svg(svg: &str) -> Result<(), String> {
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
pub fn glb_json(glb: &[u8]) -> &[u8] {
    let length = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    &glb[20..20 + length]
}

/// What is wrong with file `name` of a set (`bytes`), if anything: the
/// JSON (and the GLB's) not parseable, an SVG not well-formed or with a
/// script, the page with other than `scripts` scripts, a CSV's rows of
/// different widths, the text with a character that moves the cursor or
/// reorders what is shown.
pub fn file_problem(name: &str, bytes: &[u8], scripts: usize) -> Option<String> {
    let text = String::from_utf8_lossy(bytes);
    let ext = Path::new(name).extension().and_then(|e| e.to_str());
    let problem = match ext {
        Some("json") => serde_json::from_slice::<serde_json::Value>(bytes)
            .err()
            .map(|e| e.to_string()),
        Some("glb") => serde_json::from_slice::<serde_json::Value>(glb_json(bytes))
            .err()
            .map(|e| format!("its JSON: {e}")),
        Some("svg") => well_formed_svg(&text).err(),
        Some("html") => {
            let opened = text.matches("<script").count();
            let closed = text.matches("</script").count();
            ((opened, closed) != (scripts, scripts))
                .then(|| format!("{opened} scripts opened and {closed} closed, not {scripts}"))
        }
        Some("csv") => {
            let counts = field_counts(&text);
            (!counts.iter().all(|&n| n == counts[0])).then(|| format!("rows of {counts:?} fields"))
        }
        Some("txt") => (text.lines())
            .find(|line| *reach::escaped(line) != **line)
            .map(|line| format!("a line printed raw: {line:?}")),
        _ => None,
    };
    problem.map(|p| format!("{name}: {p}"))
}
