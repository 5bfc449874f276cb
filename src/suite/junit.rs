//! `reach test --junit FILE`: the suite as JUnit XML, which every CI
//! shows: one test suite per scenario, one test case per expectation and
//! one for the golden comparison (or, for a scenario that does not check,
//! one for the check, with its diagnostics).

use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};

use super::{Compared, Golden, Outcome};

/// The outcomes as JUnit XML.
pub fn junit(outcomes: &[Outcome]) -> String {
    let mut report = Report::new("reach test");
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
