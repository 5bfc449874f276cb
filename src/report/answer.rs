//! An answer: what one task found for one person, in words and in the
//! figures that matter, each with the tolerance within which it counts as
//! unchanged. The text report's table, watch mode's list of changes and
//! comparisons with golden reports read answers, not report fields.

/// One task's answer.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    /// The task as the text report names it: `reach`, `gaze`,
    /// `reach+gaze`, `map`, `gaze_map`.
    pub task: &'static str,
    /// The target or surface.
    pub subject: String,
    pub person: String,
    /// Reachable, visible, or (a map) at least one point is.
    pub ok: bool,
    /// In words: `reachable`, `NOT visible: behind shelf`,
    /// `83.3 % of 24 reached`.
    pub verdict: String,
    /// The effector the answer was found with (`grip`, `left_grip`), where
    /// it is a hand's: which hand reached.
    pub effector: Option<String>,
    pub figures: Vec<Figure>,
}

/// One figure of an answer.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// `distance`, `sweeps`, `comfort`, `base x`, `share`, ...
    pub name: &'static str,
    pub value: f64,
    /// `mm`, `deg`, `%`, or empty.
    pub unit: &'static str,
    /// A change up to this much is no change (infinite: the figure says
    /// how the answer was found, not what it is).
    pub tolerance: f64,
}

impl Figure {
    pub fn new(name: &'static str, value: f64, unit: &'static str, tolerance: f64) -> Self {
        Figure {
            name,
            value,
            unit,
            tolerance,
        }
    }
}

impl Answer {
    /// The figure of this name.
    pub fn figure(&self, name: &str) -> Option<&Figure> {
        self.figures.iter().find(|f| f.name == name)
    }

    /// `mug by ann`, or a standard's `ada2010 in bathroom`: how watch mode
    /// and comparisons name the answer.
    pub fn label(&self) -> String {
        match self.person.strip_prefix("in ") {
            Some(room) if self.task == "standard" => format!("{} in {room}", self.subject),
            _ => format!("{} by {}", self.subject, self.person),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Answer;

    fn answer(task: &'static str, subject: &str, person: &str) -> Answer {
        Answer {
            task,
            subject: subject.into(),
            person: person.into(),
            ok: true,
            verdict: String::new(),
            effector: None,
            figures: Vec::new(),
        }
    }

    /// A standard is checked in a room, not by a person: "ada2010 by in
    /// bathroom" read as a slip.
    #[test]
    fn a_label_names_the_person_or_a_standards_room() {
        assert_eq!(answer("reach", "mug", "ann").label(), "mug by ann");
        assert_eq!(
            answer("standard", "ada2010", "in bathroom").label(),
            "ada2010 in bathroom"
        );
    }
}
