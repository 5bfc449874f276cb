//! `reach test --junit FILE`: the suite as JUnit XML, which every CI
//! shows: one test suite per scenario, one test case per expectation and
//! one for the golden comparison (or, for a scenario that does not check,
//! one for the check, with its diagnostics).

use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};

use super::{Compared, Golden, Outcome};
use crate::scenario::ShardOf;

/// The name of the JUnit report of a whole suite.
const NAME: &str = "reach test";

/// The outcomes as JUnit XML; a shard's (`reach test --shard K/N`) named
/// `reach test shard K/N`, so that the merge knows it.
pub fn junit(outcomes: &[Outcome], shard: Option<(usize, usize)>) -> String {
    let name = match shard {
        Some((k, n)) => format!("{NAME} shard {k}/{n}"),
        None => NAME.to_string(),
    };
    let mut report = Report::new(name);
    for o in outcomes {
        let mut suite = TestSuite::new(safe(&o.path.display().to_string()));
        if let Some(d) = &o.diagnostics {
            let rendered = d.render(true);
            suite.add_test_case(failed("check", "the scenario does not check", &rendered));
        }
        for e in &o.expectations {
            let name = format!("expect {}", e.expect);
            let case = if e.met {
                TestCase::new(safe(&name), TestCaseStatus::success())
            } else {
                failed(&name, &e.because, &format!("{}: {}", e.at, e.because))
            };
            suite.add_test_case(case);
        }
        if let Some(case) = golden_case(&o.golden) {
            suite.add_test_case(case);
        }
        report.add_test_suite(suite);
    }
    report.to_string().unwrap_or_default()
}

/// The golden comparison's test case, if there was a golden report.
fn golden_case(golden: &Golden) -> Option<TestCase> {
    let name = "golden report";
    let case = match golden {
        Golden::Absent => return None,
        Golden::Compared(Compared::Same) | Golden::Written { .. } => {
            TestCase::new(name, TestCaseStatus::success())
        }
        Golden::Compared(Compared::Changed(changes)) => failed(
            name,
            &format!("{} answers changed", changes.len()),
            &changes.join("\n"),
        ),
        Golden::Compared(Compared::OtherSchema { golden }) => failed(
            name,
            &format!("written by schema {golden}: run `reach test --update`"),
            "",
        ),
        Golden::Compared(Compared::Unreadable(why)) => failed(name, why, ""),
        Golden::NotWritten { path, reason } => {
            failed(name, &format!("cannot write {}", path.display()), reason)
        }
        Golden::Shared { path, with } => failed(name, &Golden::shared_words(path, with), ""),
    };
    Some(case)
}

fn failed(name: &str, message: &str, details: &str) -> TestCase {
    let mut status = TestCaseStatus::non_success(NonSuccessKind::Failure);
    status.set_message(safe(message));
    if !details.is_empty() {
        status.set_description(safe(details));
    }
    TestCase::new(safe(name), status)
}

/// Text from a scenario (names, diagnostics quoting its lines) with its
/// control characters escaped, line by line: XML cannot hold most of them.
fn safe(text: &str) -> String {
    text.lines()
        .map(crate::escape::escaped)
        .collect::<Vec<_>>()
        .join("\n")
}

/// The JUnit files of every shard of a suite (`reach test --shard K/N`,
/// each K from 1 to N once, in any order, with the name of each file for
/// what is said of it) joined as the whole suite's file: its test suites
/// in the order of the shards; or what is wrong with them.
pub fn merge_junit(files: &[(String, String)]) -> Result<String, String> {
    let mut by_index: std::collections::BTreeMap<usize, Report> = Default::default();
    let mut count = None;
    for (name, xml) in files {
        let report = Report::deserialize_from_str(xml)
            .map_err(|e| format!("`{name}` is not JUnit XML: {e}"))?;
        let shard = (report.name.as_str().strip_prefix(NAME))
            .and_then(|rest| rest.strip_prefix(" shard "))
            .and_then(|k_n| ShardOf::parse(k_n).ok())
            .ok_or_else(|| format!("`{name}` is not the JUnit file of a shard of `reach test` (its report is named `{}`)", report.name.as_str()))?;
        if count.is_some_and(|n| n != shard.count) {
            return Err(format!(
                "`{name}` is shard {}/{}, the first given of {}",
                shard.index,
                shard.count,
                count.unwrap_or(0)
            ));
        }
        count = Some(shard.count);
        if by_index.insert(shard.index, report).is_some() {
            return Err(format!(
                "`{name}`: shard {}/{} is given twice",
                shard.index, shard.count
            ));
        }
    }
    if let Some(words) = ShardOf::missing(count.unwrap_or(0), |k| by_index.contains_key(&k)) {
        return Err(format!("{words} (of the suite)"));
    }
    let mut whole = Report::new(NAME);
    for (_, part) in by_index {
        whole.add_test_suites(part.test_suites);
    }
    whole.to_string().map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::safe;

    /// XML 1.0 holds neither most controls nor U+FFFE and U+FFFF: a file
    /// name or a diagnostic with one must not make the file ill-formed.
    #[test]
    fn text_xml_cannot_hold_is_escaped() {
        let text = safe("scene\u{FFFF}\u{FFFE}\u{1}\u{1b}.reach\nline two");
        assert!(!text
            .chars()
            .any(|c| matches!(c, '\u{FFFE}' | '\u{FFFF}' | '\u{1}' | '\u{1b}')));
        assert_eq!(text, "scene\\u{ffff}\\u{fffe}\\u{1}\\u{1b}.reach\nline two");
    }
}
