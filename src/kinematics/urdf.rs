//! A chain from a URDF robot description (read by `urdf-rs`): the joints on
//! the path from a root link to a tip link, revolute, continuous and
//! prismatic ones as joints with their limits and axes, fixed joints folded
//! into their neighbours. Each URDF joint moves about its own axis after
//! its origin; here a joint turns about the z axis of the previous frame
//! and then a fixed pose follows, so each axis is carried to z by a
//! rotation and back. A locked joint `NAME_base` carries the base frame to
//! the first axis when they differ. Lengths: URDF metres, here millimetres.

use nalgebra::{IsometryMatrix3, Rotation3, Translation3, Unit, Vector3};

use super::chain::{Chain, Joint, JointKind, Link};
use super::dh::Dh;
use crate::escape::escaped;

/// Why a URDF chain cannot be built.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UrdfError {
    UnknownLink {
        link: String,
        available: Vec<String>,
    },
    NoPath {
        root: String,
        tip: String,
    },
    Unsupported {
        joint: String,
        kind: String,
    },
    NoJoints {
        root: String,
        tip: String,
    },
    BadAxis {
        joint: String,
    },
    BadLimits {
        joint: String,
        reason: String,
    },
    BadOrigin {
        joint: String,
    },
}

/// The farthest a joint's origin may lie from its parent's, in metres:
/// far beyond any body, near enough that lengths stay exact.
const FARTHEST_ORIGIN_M: f64 = 100.0;
/// The longest a prismatic joint may slide, in metres.
const LONGEST_SLIDE_M: f64 = 100.0;

impl std::fmt::Display for UrdfError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            UrdfError::UnknownLink { link, .. } => write!(f, "it has no link `{link}`"),
            UrdfError::NoPath { root, tip } => {
                write!(f, "no chain of joints leads from `{root}` to `{tip}`")
            }
            UrdfError::Unsupported { joint, kind } => {
                write!(f, "joint `{joint}` is {kind}, which a mannequin cannot use")
            }
            UrdfError::NoJoints { root, tip } => {
                write!(f, "no joint moves between `{root}` and `{tip}`")
            }
            UrdfError::BadAxis { joint } => {
                write!(f, "joint `{joint}` has a zero or not finite axis")
            }
            UrdfError::BadLimits { joint, reason } => {
                write!(f, "joint `{joint}`'s limits {reason}")
            }
            UrdfError::BadOrigin { joint } => write!(
                f,
                "joint `{joint}`'s origin is not finite or lies more than {FARTHEST_ORIGIN_M} m \
                 from its parent"
            ),
        }
    }
}

/// The chain from link `root` to link `tip`, its effector at the tip
/// link's origin, named after it.
pub fn chain_from_urdf(robot: &urdf_rs::Robot, root: &str, tip: &str) -> Result<Chain, UrdfError> {
    for link in [root, tip] {
        if !robot.links.iter().any(|l| l.name == link) {
            return Err(UrdfError::UnknownLink {
                link: link.to_string(),
                available: robot.links.iter().map(|l| l.name.clone()).collect(),
            });
        }
    }
    let path = path(robot, root, tip)?;
    let mut joints: Vec<Joint> = Vec::new();
    // The pose, in the frame after the last motion, reached so far.
    let mut pending = IsometryMatrix3::identity();
    // A pose before the first joint that commutes with its motion (an
    // offset along, or a turn about, the base's z): it joins that joint's
    // fixed pose instead of needing a locked joint.
    let mut first_pre = IsometryMatrix3::identity();
    let mut first_index = None;
    for j in path {
        let origin = pose_mm(&j.origin).ok_or_else(|| UrdfError::BadOrigin {
            joint: j.name.clone(),
        })?;
        let kind = match j.joint_type {
            urdf_rs::JointType::Fixed => {
                pending *= origin;
                continue;
            }
            urdf_rs::JointType::Revolute | urdf_rs::JointType::Continuous => JointKind::Revolute,
            urdf_rs::JointType::Prismatic => JointKind::Prismatic,
            ref other => {
                return Err(UrdfError::Unsupported {
                    joint: j.name.clone(),
                    kind: format!("{other:?}").to_lowercase(),
                })
            }
        };
        let to_axis = z_onto(&j.axis.xyz).ok_or_else(|| UrdfError::BadAxis {
            joint: j.name.clone(),
        })?;
        let before = pending * origin * to_axis;
        match joints.len().checked_sub(1) {
            Some(k) => joints[k].fixed = Some(pre(first_index, k, &first_pre) * before),
            None if along_z(&before) => first_pre = before,
            None => joints.push(Joint::locked(&format!("{}_base", shown(&j.name)), before)),
        }
        first_index.get_or_insert(joints.len());
        joints.push(moving(j, kind)?);
        pending = to_axis.inverse();
    }
    let Some(k) = joints.len().checked_sub(1) else {
        return Err(UrdfError::NoJoints {
            root: root.into(),
            tip: tip.into(),
        });
    };
    joints[k].fixed = Some(pre(first_index, k, &first_pre) * pending);
    Ok(Chain::new(joints, tip, Vector3::zeros()))
}

/// `first_pre` for the first moving joint, nothing for the others.
fn pre(
    first_index: Option<usize>,
    k: usize,
    first_pre: &IsometryMatrix3<f64>,
) -> IsometryMatrix3<f64> {
    if first_index == Some(k) {
        *first_pre
    } else {
        IsometryMatrix3::identity()
    }
}

/// Whether a pose only moves along, or turns about, the z axis.
fn along_z(pose: &IsometryMatrix3<f64>) -> bool {
    let t = pose.translation.vector;
    let z = pose.rotation * Vector3::z();
    t.x.abs() < 1e-9 && t.y.abs() < 1e-9 && (z - Vector3::z()).norm() < 1e-12
}

/// The joints from `root` down to `tip`, in order.
fn path<'r>(
    robot: &'r urdf_rs::Robot,
    root: &str,
    tip: &str,
) -> Result<Vec<&'r urdf_rs::Joint>, UrdfError> {
    // Each link's parent joint, the first one listed: one pass, however
    // many joints the file has.
    let mut parent_joint: std::collections::HashMap<&str, &urdf_rs::Joint> =
        std::collections::HashMap::with_capacity(robot.joints.len());
    for j in robot.joints.iter().rev() {
        parent_joint.insert(j.child.link.as_str(), j);
    }
    let mut chain = Vec::new();
    let mut link = tip;
    while link != root {
        let Some(&j) = parent_joint.get(link) else {
            return Err(UrdfError::NoPath {
                root: root.into(),
                tip: tip.into(),
            });
        };
        if chain.len() > robot.joints.len() {
            return Err(UrdfError::NoPath {
                root: root.into(),
                tip: tip.into(),
            });
        }
        chain.push(j);
        link = &j.parent.link;
    }
    chain.reverse();
    Ok(chain)
}

/// A URDF pose (metres, roll-pitch-yaw) in millimetres; none if a number
/// is not finite or the offset is farther than [`FARTHEST_ORIGIN_M`].
fn pose_mm(p: &urdf_rs::Pose) -> Option<IsometryMatrix3<f64>> {
    let [x, y, z] = *p.xyz;
    let [roll, pitch, yaw] = *p.rpy;
    let finite = p.xyz.iter().chain(p.rpy.iter()).all(|v| v.is_finite());
    if !finite || x.hypot(y).hypot(z) > FARTHEST_ORIGIN_M {
        return None;
    }
    Some(IsometryMatrix3::from_parts(
        Translation3::new(x * 1000.0, y * 1000.0, z * 1000.0),
        Rotation3::from_euler_angles(roll, pitch, yaw),
    ))
}

/// A rotation taking the z axis onto `axis` (none for a zero or not
/// finite axis).
fn z_onto(axis: &[f64; 3]) -> Option<IsometryMatrix3<f64>> {
    if !axis.iter().all(|v| v.is_finite()) {
        return None;
    }
    // Scaled by its largest component first, so that a huge axis (1e300)
    // keeps its direction instead of overflowing to no direction at all.
    let largest = axis.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if largest == 0.0 {
        return None;
    }
    let a = Vector3::from(*axis) / largest;
    let a = Unit::try_new(a, 1e-12)?;
    let rotation = Rotation3::rotation_between(&Vector3::z(), &a)
        .unwrap_or_else(|| Rotation3::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI));
    Some(IsometryMatrix3::from_parts(
        Translation3::identity(),
        rotation,
    ))
}

fn moving(j: &urdf_rs::Joint, kind: JointKind) -> Result<Joint, UrdfError> {
    let (min, max) = match (&j.joint_type, kind) {
        (urdf_rs::JointType::Continuous, _) => (-std::f64::consts::PI, std::f64::consts::PI),
        (_, JointKind::Prismatic) => {
            let (lower, upper) = limits(j, LONGEST_SLIDE_M, "m")?;
            (lower * 1000.0, upper * 1000.0)
        }
        _ => limits(j, 2.0 * std::f64::consts::PI, "rad (360 deg)")?,
    };
    Ok(Joint {
        name: shown(&j.name),
        kind,
        dh: Dh::default(),
        fixed: Some(IsometryMatrix3::identity()),
        pre: None,
        min,
        max,
        anatomical: None,
        neutral: 0.0_f64.clamp(min, max),
        weight: 1.0,
        link: Link::named(&shown(&j.name)),
    })
}

/// A joint's lower and upper limits, if they are finite, in order and
/// within `+/-largest` (in `unit`).
fn limits(j: &urdf_rs::Joint, largest: f64, unit: &str) -> Result<(f64, f64), UrdfError> {
    let (lower, upper) = (j.limit.lower, j.limit.upper);
    let bad = |reason: String| UrdfError::BadLimits {
        joint: j.name.clone(),
        reason,
    };
    if !lower.is_finite() || !upper.is_finite() {
        return Err(bad(format!("({lower}, {upper}) are not finite numbers")));
    }
    if lower > upper {
        return Err(bad(format!(
            "have the lower {lower} above the upper {upper}"
        )));
    }
    if lower < -largest || upper > largest {
        return Err(bad(format!(
            "({lower}, {upper}) go beyond +/-{largest:.4} {unit}"
        )));
    }
    Ok((lower, upper))
}

/// A joint's name as the chain keeps it: escaped, so that a name in a file
/// (where XML allows `&#10;` or a bidirectional override) can never forge
/// a line of a report or reorder it on a terminal.
fn shown(name: &str) -> String {
    escaped(name).into_owned()
}

#[cfg(test)]
mod axis_tests {
    use super::z_onto;
    use nalgebra::Vector3;

    #[test]
    fn a_huge_axis_keeps_its_direction_and_a_bad_one_has_none() {
        for (axis, expected) in [
            ([0.0, 1e300, 0.0], Vector3::y()),
            ([0.0, 2.0, 0.0], Vector3::y()),
            ([-1e300, 0.0, 0.0], -Vector3::x()),
        ] {
            let turned = z_onto(&axis).unwrap().rotation * Vector3::z();
            assert!((turned - expected).norm() < 1e-12, "{axis:?}: {turned}");
        }
        for axis in [
            [0.0, 0.0, 0.0],
            [0.0, f64::INFINITY, 0.0],
            [f64::NAN, 1.0, 0.0],
        ] {
            assert!(z_onto(&axis).is_none(), "{axis:?}");
        }
    }
}
