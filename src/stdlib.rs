//! The standard library's mannequins, checked as a scenario would check
//! them, for programs, tests and benchmarks (the module texts themselves
//! are in `std_modules.rs`, below the loader that reads them).

/// The body of mannequin `name` of module `std::module`, checked as a
/// scenario would check it (for programs, tests and benchmarks).
pub fn body(module: &str, name: &str) -> Result<crate::kinematics::Body, crate::Diagnostics> {
    let text =
        format!("use std::{module}\nperson p {{ mannequin {name} base fixed {{ at (0, 0, 0) }} }}");
    let input = crate::Input::Text {
        name: "stdlib.reach",
        text: &text,
    };
    let (_, checked) = crate::check(input, &crate::plugin::Registry::builtin());
    checked.map(|scenario| scenario.persons[0].body.clone())
}

/// The chain to the first effector of mannequin `name` of `std::module`.
pub fn chain(module: &str, name: &str) -> Result<crate::kinematics::Chain, crate::Diagnostics> {
    body(module, name).map(|b| b.chain(0))
}

/// What `reach stdlib NAME` prints: where `name` is declared, the comment
/// above its declaration (which names the sources of its figures), the
/// declaration itself and, for a mannequin that needs no parameters, the
/// body a scenario gets from it: each joint's limits and link, the
/// effectors and the legs. Where no module declares `name`, the declared
/// name closest to it, if one is close.
pub fn describe(name: &str) -> Result<String, Option<String>> {
    // A module's name: its part of the listing.
    let module = name.strip_prefix("std::").unwrap_or(name);
    if let Some(text) = crate::std_texts::module(module) {
        return Ok(crate::std_modules::entry(module, text));
    }
    let found = KINDS
        .iter()
        .find_map(|k| crate::std_texts::home_of(k, name).map(|m| (*k, m)));
    let Some((keyword, module)) = found else {
        let known = declared_names();
        let suggestions = crate::names::Suggestions::default();
        return Err(suggestions.suggest(name, known.iter().map(String::as_str)));
    };
    let text = crate::std_texts::module(module).unwrap_or_default();
    let lines: Vec<&str> = text.lines().collect();
    let at = lines
        .iter()
        .position(|l| crate::std_texts::declares(l, keyword, name))
        .unwrap_or_default();
    let mut out = format!("{keyword} {name}: std::{module} (`use std::{module}`)\n\n");
    // The comment above it, or above the run of one-line declarations of
    // its kind it is one of (`base manual_wheelchair = ...` and the next).
    let run_start = lines[..at]
        .iter()
        .rposition(|l| !l.starts_with(keyword))
        .map_or(0, |k| k + 1);
    let comment_start = lines[..run_start]
        .iter()
        .rposition(|l| !l.trim_start().starts_with("//"))
        .map_or(0, |k| k + 1);
    for line in &lines[comment_start..run_start] {
        out.push_str(line);
        out.push('\n');
    }
    let declared = declaration(&lines[at..]);
    for line in &declared {
        out.push_str(line);
        out.push('\n');
    }
    let declared = declared.join("\n");
    if keyword == "base" {
        out.push_str(&base_defaults(&declared));
    }
    if keyword == "mannequin" {
        let chain = built_from(&declared);
        if !chain.is_empty() {
            out.push_str(&format!(
                "\nBuilt from {}: `reach stdlib NAME` shows each, with the sources of its figures \
                 (docs/references.md gives them in full).\n",
                chain.join(", then ")
            ));
        }
        out.push('\n');
        match body(module, name) {
            Ok(b) => out.push_str(&body_table(&b)),
            Err(_) => out.push_str(
                "(its body depends on the parameters a person gives: see the comment above)\n",
            ),
        }
    }
    Ok(out)
}

/// The kinds of declaration `reach stdlib NAME` describes.
const KINDS: [&str; 5] = ["mannequin", "profile", "base", "vision", "population"];

/// Every name the standard library's modules declare, of [`KINDS`].
fn declared_names() -> Vec<String> {
    let mut names = Vec::new();
    for (_, text) in crate::std_texts::MODULES {
        for line in text.lines() {
            for keyword in KINDS {
                let Some(rest) = line.strip_prefix(keyword).and_then(|r| r.strip_prefix(' '))
                else {
                    continue;
                };
                let name = leading_name(rest);
                if !name.is_empty() {
                    names.push(name);
                }
            }
        }
    }
    names
}

/// The mannequins a mannequin's declaration is built from, in order
/// (`woman_5th_seated` from `woman_5th`, from `measured`, from
/// `upper_body`), each as `` `name` ``.
fn built_from(declared: &str) -> Vec<String> {
    let mut chain = Vec::new();
    let mut text = declared.to_string();
    while let Some(rest) = after_alias_sign(&text) {
        let next = leading_name(rest);
        let Some(module) = crate::std_texts::home_of("mannequin", &next) else {
            break;
        };
        if chain.len() > 8 || chain.contains(&format!("`{next}`")) {
            break;
        }
        chain.push(format!("`{next}`"));
        let lines: Vec<&str> = crate::std_texts::module(module)
            .unwrap_or_default()
            .lines()
            .collect();
        let Some(at) = lines
            .iter()
            .position(|l| crate::std_texts::declares(l, "mannequin", &next))
        else {
            break;
        };
        text = declaration(&lines[at..]).join("\n");
    }
    chain
}

/// What follows a declaration's `=` outside its brackets, comments and
/// strings (the mannequin or plugin it is built from), if it has one.
fn after_alias_sign(declared: &str) -> Option<&str> {
    let mut depth = 0i64;
    for (at, b) in crate::syntax::code_bytes(declared) {
        match b {
            b'(' | b'{' => depth += 1,
            b')' | b'}' => depth -= 1,
            b'=' if depth == 0 => return Some(&declared[at + 1..]),
            _ => {}
        }
    }
    None
}

/// The name `text` starts with, after any spaces.
fn leading_name(text: &str) -> String {
    text.trim_start()
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect()
}

/// The options a base preset leaves at its plugin's defaults, each with
/// its value and what it is.
fn base_defaults(declared: &str) -> String {
    let plugin = after_alias_sign(declared)
        .map(leading_name)
        .unwrap_or_default();
    let registry = crate::plugin::Registry::builtin();
    let Some(params) = registry.params(crate::plugin::PluginKind::Base, &plugin) else {
        return String::new();
    };
    let given = |name: &str| {
        declared
            .split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .any(|word| word == name)
    };
    let mut out = format!("\nIts other options, at the `{plugin}` plugin's defaults:\n");
    for param in params.iter().filter(|p| !given(p.name)) {
        let value = param
            .default
            .as_ref()
            .map_or_else(|| "(none)".to_string(), |v| v.display());
        out.push_str(&format!(
            "  {:<22} {:<14} {}\n",
            param.name, value, param.doc
        ));
    }
    out
}

/// The lines of the declaration that starts `lines`: up to the line where
/// its parentheses and braces (outside comments and strings) are all
/// closed again.
fn declaration<'t>(lines: &[&'t str]) -> Vec<&'t str> {
    let mut depth = 0i64;
    for (k, line) in lines.iter().enumerate() {
        for (_, b) in crate::syntax::code_bytes(line) {
            match b {
                b'(' | b'{' => depth += 1,
                b')' | b'}' => depth -= 1,
                _ => {}
            }
        }
        if depth <= 0 {
            return lines[..=k].to_vec();
        }
    }
    lines.to_vec()
}

/// The body's joints (limits, which way is positive, the link each
/// moves), effectors and legs, as a table.
pub fn body_table(body: &crate::kinematics::Body) -> String {
    use crate::kinematics::JointKind;
    let mut out = String::from(
        "The body a scenario gets: each joint's limits (deg, or mm for a joint that slides; \
         0 is standing upright, the arm hanging, palm forward, looking ahead), which way is \
         positive, and the link the joint moves, from its centre to the next joint's \
         (its length and its solid's radius, mm):\n",
    );
    if let Some(stance) = body.posture {
        out.push_str(&format!("  posture: {}\n", stance.word()));
    }
    out.push_str(&format!(
        "  {:<24} {:>18}  {:<34} {}\n",
        "joint", "limits", "positive", "link it moves"
    ));
    for joint in &body.joints {
        let (min, max, unit) = match joint.kind {
            JointKind::Revolute => (joint.min.to_degrees(), joint.max.to_degrees(), ""),
            JointKind::Prismatic => (joint.min, joint.max, " mm"),
        };
        let origin = nalgebra::Point3::from(joint.rest_offset_mm());
        let link_mm = (joint.axis_frame() * origin).coords.norm();
        let link = match link_mm > 0.05 {
            true => format!(
                "{} {link_mm:.1} (radius {:.1})",
                joint.link.name, joint.link.radius_mm
            ),
            false => "-".to_string(),
        };
        let limits = format!("{min:.1} to {max:.1}{unit}");
        out.push_str(&format!(
            "  {:<24} {limits:>18}  {:<34} {link}\n",
            joint.name,
            positive_way(&joint.name)
        ));
    }
    let effectors: Vec<String> = body
        .effectors
        .iter()
        .map(|e| match e.joint {
            Some(j) => format!(
                "{} ({:.1} past {})",
                e.name,
                e.offset_mm.norm(),
                body.joints[j].name
            ),
            None => e.name.clone(),
        })
        .collect();
    out.push_str(&format!("  effectors: {}\n", effectors.join(", ")));
    if let Some(legs) = &body.legs {
        out.push_str(&format!(
            "  legs: hip {:.0}, knee {:.0}, ankle {:.0} above the floor standing; foot {:.0}; \
             hips {:.0} apart; seated, the hip point {:.0} above the seat\n",
            legs.hip_height_mm,
            legs.knee_height_mm,
            legs.ankle_height_mm,
            legs.foot_mm,
            legs.hip_width_mm,
            legs.hip_above_seat_mm
        ));
    }
    out
}

/// Which way a joint of the standard library's bodies turns when its
/// angle is positive (std::body's and std::people's comments; a left
/// arm's joints as the right's, mirrored); blank for a joint not known.
fn positive_way(joint: &str) -> &'static str {
    match joint.strip_prefix("left_").unwrap_or(joint) {
        "trunk_flexion" => "leaning forward",
        "shoulder_elevation" => "the girdle's rise, follows the arm",
        "shoulder_flexion" => "flexion (forward); - extension",
        "shoulder_abduction" => "abduction (out to the side)",
        "shoulder_rotation" => "lateral; - medial rotation",
        "elbow_flexion" => "flexion",
        "forearm_rotation" => "supination; - pronation (assumed)",
        "wrist_flexion" => "flexion (palm-ward); - extension",
        "wrist_deviation" => "ulnar; - radial deviation",
        "neck_extension" => "extension (head back); - flexion",
        "neck_lateral" => "bending to the right",
        "neck_rotation" => "turning to the left",
        "eye_pitch" => "looking up",
        "eye_yaw" => "looking to the left",
        "look" => "the line of sight's length",
        _ => "",
    }
}
