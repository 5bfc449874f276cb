//! Where one element is advised for several groups (populations and named
//! people: a household, or the users a kitchen is designed for), the
//! positions that serve every one of them at once: each population at
//! least the share its advice asks, each person reaching it. A report's
//! own entry, beside the advices it combines.

use serde::Serialize;

use super::{AdviceReport, TaskReport};

/// The positions that serve every group advised about one element.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct AdvisedTogether {
    /// The target (`kettle-x` where it is advised along another axis too:
    /// the name its plot is written under).
    pub name: String,
    /// The room's axis the element moves along: `x`, `y` or `z`.
    pub along: &'static str,
    /// Each group, as its advice names it, in the order of the file.
    pub who: Vec<String>,
    /// The runs of positions at which every group is served, in order.
    pub ranges: Vec<Span>,
}

/// A run of positions, both ends served.
#[derive(Clone, Debug, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Span {
    pub from_mm: f64,
    pub to_mm: f64,
}

impl AdvisedTogether {
    /// One entry for each element advised for two or more groups, in the
    /// order each element first comes in `tasks`; none for a target an
    /// advice about which has no answer (a run stopped before it): which
    /// positions serve every group cannot be told.
    pub fn of(tasks: &[TaskReport]) -> Vec<AdvisedTogether> {
        let unanswered = |name: &str| {
            (tasks.iter()).any(|t| {
                let answer = t.answer();
                !matches!(t, TaskReport::Advice(_))
                    && answer.task == "advise"
                    && answer.subject == name
            })
        };
        (by_target(tasks).into_iter())
            .filter(|(_, advices)| advices.len() > 1 && !unanswered(&advices[0].name))
            .map(|(name, advices)| AdvisedTogether {
                name,
                along: advices[0].along,
                who: advices.iter().map(|a| a.who.clone()).collect(),
                ranges: (AdviceReport::served_together(&advices).into_iter())
                    .map(|(from_mm, to_mm)| Span { from_mm, to_mm })
                    .collect(),
            })
            .collect()
    }

    /// `microwave_handle's z, serving every group (manual_users, ann):
    /// 700-1450 mm`.
    pub fn words(&self) -> String {
        let ranges: Vec<String> = (self.ranges.iter())
            .map(|s| match s.from_mm == s.to_mm {
                true => format!("{} mm", s.from_mm),
                false => format!("{}-{} mm", s.from_mm, s.to_mm),
            })
            .collect();
        let ranges = match ranges.is_empty() {
            true => "nowhere in the scan".to_string(),
            false => ranges.join(", "),
        };
        format!(
            "{}'s {}, serving every group ({}): {ranges}",
            self.name,
            self.along,
            self.who.join(", ")
        )
    }
}

/// The advices of `tasks` along one line, by target and axis, in the
/// order each first comes, each group named after its target (and its
/// axis, where the target is advised along another axis too: `kettle-x`).
/// Grids are not among them: each is plotted on its own, and is served
/// together with no other.
pub fn by_target(tasks: &[TaskReport]) -> Vec<(String, Vec<&AdviceReport>)> {
    let mut out: Vec<(String, Vec<&AdviceReport>)> = Vec::new();
    for task in tasks {
        let TaskReport::Advice(a) = task else {
            continue;
        };
        if !a.rows.is_empty() {
            continue;
        }
        let same = |e: &[&AdviceReport]| e[0].name == a.name && e[0].along == a.along;
        match out.iter_mut().find(|(_, e)| same(e)) {
            Some((_, each)) => each.push(a),
            None => out.push((a.name.clone(), vec![a])),
        }
    }
    for k in 0..out.len() {
        let twin = (0..out.len()).any(|j| j != k && out[j].1[0].name == out[k].1[0].name);
        if twin {
            out[k].0 = format!("{}-{}", out[k].1[0].name, out[k].1[0].along);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::{AdviceFrame, PositionAnswer};

    fn frame(name: &str, along: &'static str, serves: f64) -> AdviceFrame {
        let positions = [600.0, 700.0, 800.0, 900.0, 1000.0, 1100.0];
        AdviceFrame {
            name: name.into(),
            along,
            ..crate::report::advice::tests::frame(&positions, serves)
        }
    }

    fn answers(bits: &str) -> Vec<PositionAnswer> {
        (bits.chars())
            .map(|c| PositionAnswer {
                reached: c == '1',
                verdict: None,
            })
            .collect()
    }

    fn person(name: &str, along: &'static str, who: &str, bits: &str) -> TaskReport {
        let a = AdviceReport::person(&frame(name, along, 0.9), who, &answers(bits));
        TaskReport::Advice(Box::new(a))
    }

    #[test]
    fn every_group_is_served_only_where_each_is_and_one_group_has_no_entry() {
        let members: Vec<(String, Vec<PositionAnswer>)> = ["011111", "011110", "111100"]
            .iter()
            .enumerate()
            .map(|(k, b)| (format!("p#{}", k + 1), answers(b)))
            .collect();
        // Two of three (67 %) serve 66 %: 700-1000 mm.
        let population = AdviceReport::population(&frame("oven", "z", 0.66), "p", &members);
        let tasks = vec![
            TaskReport::Advice(Box::new(population)),
            person("oven", "z", "ann", "110111"),
            person("kettle", "z", "ann", "111111"),
        ];
        let together = AdvisedTogether::of(&tasks);
        assert_eq!(together.len(), 1, "the kettle has one group: {together:?}");
        assert_eq!(together[0].who, ["p", "ann"]);
        let ranges: Vec<(f64, f64)> = (together[0].ranges.iter())
            .map(|s| (s.from_mm, s.to_mm))
            .collect();
        assert_eq!(ranges, [(700.0, 700.0), (900.0, 1000.0)]);
        assert_eq!(
            together[0].words(),
            "oven's z, serving every group (p, ann): 700 mm, 900-1000 mm"
        );
    }

    #[test]
    fn a_target_advised_along_two_axes_is_two_entries_named_by_axis() {
        let tasks = vec![
            person("oven", "z", "ann", "011000"),
            person("oven", "x", "ann", "000000"),
            person("oven", "z", "ben", "001100"),
            person("oven", "x", "ben", "111111"),
        ];
        let together = AdvisedTogether::of(&tasks);
        let names: Vec<&str> = together.iter().map(|t| t.name.as_str()).collect();
        assert_eq!(names, ["oven-z", "oven-x"]);
        assert_eq!(
            together[0].ranges,
            [Span {
                from_mm: 800.0,
                to_mm: 800.0
            }]
        );
        assert!(together[1].ranges.is_empty());
        assert!(together[1].words().ends_with("nowhere in the scan"));
    }
}
