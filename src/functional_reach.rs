//! Standing forward reach taken on the model as Duncan et al. took
//! *functional reach* on people (1990; docs/calibration.md, "Standing
//! forward reach"): standing, feet fixed, how far the hand moves forward at
//! shoulder height from the arm held straight forward to the farthest
//! reach. On the model, by the tool's own search: a standing mannequin on
//! a fixed base in an empty room, reach targets in 5 mm steps straight
//! ahead at the grip's height with the arm straight forward; a low box just
//! ahead of the toes keeps the feet from going forward of where they
//! stood, and the hips are put 0 to 150 mm behind the ankles (they go back
//! as a person leans). The farthest target reached, less where the grip is
//! with the arm straight forward and the trunk upright.

use crate::kinematics::Body;
use crate::plugin::Registry;
use crate::report::TaskReport;
use crate::{Diagnostics, Input};

/// How far behind the ankles the hips are put.
const HIPS_BACK_MM: [f64; 7] = [0.0, 25.0, 50.0, 75.0, 100.0, 125.0, 150.0];
const STEP_MM: f64 = 5.0;
/// Targets from 100 mm short of the arm straight forward, this many.
const STEPS: usize = 160;
/// The ankles' place in the room.
const ANKLE_X_MM: f64 = 1000.0;

/// A mannequin's functional reach, millimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FunctionalReach {
    /// The grip ahead of the ankles with the arm straight forward, the
    /// trunk upright, the hips over the ankles.
    pub arm_forward_mm: f64,
    /// The farthest target reached, ahead of the ankles.
    pub farthest_mm: f64,
}

impl FunctionalReach {
    /// Their difference: the functional reach.
    pub fn reach_mm(&self) -> f64 {
        self.farthest_mm - self.arm_forward_mm
    }
}

/// Why a mannequin cannot be measured so.
#[derive(Debug)]
pub enum Unmeasured {
    /// No `grip` with a `shoulder_flexion` on its chain, or no legs.
    NotStdBody,
    /// The scenario built for it does not check or run.
    Scenario(String),
}

impl From<Diagnostics> for Unmeasured {
    fn from(d: Diagnostics) -> Self {
        Unmeasured::Scenario(d.render(false))
    }
}

/// The functional reach of `mannequin` (a standing one with std::body's
/// names, as a `mannequin` line of a `.reach` file with `use std::people`
/// gives it: `man_50th`, `measured(...)`), `body` being what it builds.
pub fn functional_reach(mannequin: &str, body: &Body) -> Result<FunctionalReach, Unmeasured> {
    let (arm_forward_mm, height_mm) = arm_forward(body).ok_or(Unmeasured::NotStdBody)?;
    let legs = body.legs.as_ref().ok_or(Unmeasured::NotStdBody)?;
    let toe_mm = legs.toe_ahead_of_ankle_mm();
    let registry = Registry::builtin();
    let mut farthest_mm = f64::NAN;
    for back_mm in HIPS_BACK_MM {
        let scenario = scenario(
            mannequin,
            legs.hip_height_mm,
            toe_mm,
            back_mm,
            height_mm,
            arm_forward_mm,
        );
        let input = Input::Text {
            name: "functional_reach.reach",
            text: &scenario,
        };
        let (_, checked) = crate::check(input, &registry);
        let report = crate::run(&checked?).map_err(|e| Unmeasured::Scenario(e.to_string()))?;
        for task in &report.tasks {
            if let TaskReport::Reach(r) = task {
                if r.ok {
                    farthest_mm = farthest_mm.max(r.target_mm[0] - ANKLE_X_MM);
                }
            }
        }
    }
    Ok(FunctionalReach {
        arm_forward_mm,
        farthest_mm,
    })
}

/// The grip with the arm straight forward, the trunk upright: how far
/// ahead of the hip point, and how high above the floor.
fn arm_forward(body: &Body) -> Option<(f64, f64)> {
    let chain = body.chain_named(Some("grip"))?;
    let mut q = vec![0.0; chain.dof()];
    let flexion = chain
        .joints
        .iter()
        .position(|j| j.name == "shoulder_flexion")?;
    q[flexion] = 90f64.to_radians();
    let grip = chain.effector(&q);
    Some((grip.x, body.legs.as_ref()?.hip_height_mm + grip.z))
}

/// The scenario with the hips `back_mm` behind the ankles.
fn scenario(
    mannequin: &str,
    hip_height_mm: f64,
    toe_mm: f64,
    back_mm: f64,
    height_mm: f64,
    arm_forward_mm: f64,
) -> String {
    let mut text =
        String::from("units mm deg\nuse std::people\nroom gym {\n  size 4000 x 3000 x 2500\n");
    let toe_x = ANKLE_X_MM + toe_mm + 1.0;
    text += &format!("  box toe_stop at ({toe_x}, 1000, 0) size (50, 1000, 150)\n");
    let names: Vec<String> = (0..STEPS).map(|k| format!("t{k}")).collect();
    for (k, name) in names.iter().enumerate() {
        let x = ANKLE_X_MM + arm_forward_mm - 100.0 + k as f64 * STEP_MM;
        text += &format!("  target {name} at ({x}, 1500, {height_mm})\n");
    }
    let hip_x = ANKLE_X_MM - back_mm;
    text += &format!(
        "}}\nperson p {{ mannequin {mannequin} base fixed {{ at ({hip_x}, 1500, {hip_height_mm}) heading 0 }} }}\n"
    );
    text += &format!(
        "reach {} by p {{ hand right tolerance 2mm }}\n",
        names.join(", ")
    );
    text
}
