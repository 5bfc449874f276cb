//! Parse errors in the user's words: what was expected (described, never as
//! a grammar rule name) and what was found instead.

use pest::error::{ErrorVariant, InputLocation};

use super::grammar::Rule;
use crate::error::{Error, ErrorKind};
use crate::span::{FileId, Span};

/// What a rule looks like to a user, or `None` for rules a user never needs
/// to hear of (their first token is described instead).
fn describe(rule: Rule) -> Option<&'static str> {
    use Rule::*;
    Some(match rule {
        EOI => "end of file",
        file | inline_space | WHITESPACE | COMMENT | line_comment | block_comment | item
        | ident_char | prefix | infix | primary | room_item | mannequin_item | joint_prop
        | person_item | joint_override | and_task | mesh_prop | link_prop | population_item => {
            return None
        }
        ident | keyword => "a name",
        number | quantity => "a number",
        unit | bad_unit | percent => "a unit",
        string | string_inner => "a string in double quotes",
        boolean => "`true` or `false`",
        expr | neg | paren => "an expression",
        call | function => "`min(...)` or `max(...)`",
        add | sub | mul | div => "an operator",
        vec3 => "a point `(x, y, z)`",
        units_decl => "`units`",
        unit_word => "a unit (mm, cm, m, in, deg, rad, arcmin)",
        use_decl => "`use`",
        std_path => "`std::name` or a \"file.reach\" path",
        let_decl => "`let`",
        limits_decl => "`limits`",
        room => "`room`",
        room_size | size_dims => "`size`",
        box_decl => "`box`",
        target_decl => "`target`",
        mesh_decl => "`mesh`",
        mesh_at => "`at (x, y, z)`",
        mesh_scale => "`scale`",
        mesh_rotate => "`rotate`",
        mesh_unit => "`unit`",
        mesh_up => "`up`",
        surface_decl => "`surface`",
        mannequin => "`mannequin`",
        joint_decl => "`joint`",
        joint_kind => "`revolute`, `prismatic` or `fixed`",
        after => "`after JOINT`",
        dh => "`dh(...)`",
        dh_param => "a DH parameter (theta, d, alpha, a)",
        limits => "`limits(min, max)`",
        anatomical => "`anatomical(min, max)`",
        neutral => "`neutral`",
        weight => "`weight`",
        effector_decl => "`effector`",
        radius => "`radius`",
        link_name => "`link NAME`",
        effector_point => "`point \"what the point is\"`",
        sphere_decl => "`sphere`",
        legs_decl => "`legs(...)`",
        couple_decl => "`couple`",
        rhythm_decl => "`rhythm FOLLOWER with JOINT, JOINT from ANGLE`",
        with_kw => "`with`",
        require_decl => "`require VALUE <= BOUND, \"why\"`",
        from_kw => "`from`",
        point_list => "a list of points",
        name_list => "a list of names `[a, b]`",
        expect_advice => "`advise TARGET serves SHARE between LOW and HIGH`",
        advise_kw => "`advise`",
        serves_kw => "`serves`",
        between_kw => "`between`",
        and_kw => "`and`",
        posture => "`seated` or `standing`",
        mannequin_alias => "`= mannequin(...)`",
        mannequin_urdf => "`from urdf \"file\" root \"link\" tip \"link\"`",
        mannequin_params | call_args => "parameters `(...)`",
        param_decl => "a parameter `name = default`",
        mannequin_ref => "a mannequin's name",
        call_arg => "a parameter `name value`",
        profile | profile_use => "`profile`",
        base_preset => "`base`",
        vision_preset | person_vision => "`vision`",
        person => "`person`",
        person_mannequin => "`mannequin`",
        population => "`population`",
        standard => "`standard`",
        expect => "`expect`",
        expect_person | expect_share | expect_meets => "an expectation: `PERSON reaches TARGET`, `share(POPULATION, TARGET) >= N %` or `ROOM meets STANDARD`",
        negation => "`not`",
        verb => "`reaches`, `sees` or `covers`",
        share_kw => "`share`",
        meets => "`meets`",
        bound | comparison => "a bound `>= 80 %`",
        in_room => "`in`",
        except | except_word => "`except`",
        door_decl => "`door`",
        vec2 => "a point `(x, y)`",
        population_from => "`= POPULATION`",
        population_size => "`size`",
        population_seed => "`seed`",
        population_women => "`women`",
        population_draw => "`draw`",
        distribution | distribution_kind => "`normal(mean, sd)` or `uniform(low, high)`",
        population_profile => "`profile NAME SHARE`",
        population_choice | one_of => "`profile one of (NAME SHARE, ...)`",
        choice_share => "a profile and its share `NAME SHARE`",
        limit_override => "`limits`",
        neutral_override => "`neutral`",
        weight_override => "`weight`",
        person_base => "`base`",
        plugin_use | plugin_block => "a plugin name",
        options => "an option block `{ ... }`",
        option => "an option name",
        option_value => "an option value",
        task => "a declaration or task",
        subject_list | subject => "a target name",
        ident_list => "a person's name",
    })
}

/// Convert a pest error into a diagnostic with a span on the offending text.
pub(super) fn syntax_error(file: FileId, text: &str, e: pest::error::Error<Rule>) -> Error {
    let mut pos = match e.location {
        InputLocation::Pos(p) => p,
        InputLocation::Span((s, _)) => s,
    };
    let mut expected: Vec<String> = Vec::new();
    if let ErrorVariant::ParsingError { positives, .. } = &e.variant {
        for r in positives {
            if let Some(d) = describe(*r) {
                push_unique(&mut expected, d.to_string());
            }
        }
    }
    if let Some(attempts) = e.parse_attempts() {
        let tokens: Vec<String> = attempts
            .expected_tokens()
            .iter()
            .map(|t| t.to_string())
            .filter(|t| is_visible_token(t))
            .map(|t| format!("`{t}`"))
            .collect();
        // The furthest place the parser got to is where the text went wrong,
        // if the parser knows what it wanted there.
        if attempts.max_position > pos && !tokens.is_empty() {
            pos = attempts.max_position;
            expected.clear();
        }
        if attempts.max_position == pos {
            for t in tokens {
                push_unique(&mut expected, t);
            }
        }
    }
    collapse_item_starts(&mut expected);
    collapse_number_continuations(&mut expected);
    if expected.is_empty() {
        expected.push("valid syntax".to_string());
    }
    let (found, len) = found_at(text, pos);
    // At the end of the file, point at the last token so the label shows.
    let (pos, len) = if len == 0 {
        last_token(text)
    } else {
        (pos, len)
    };
    let wants_brace = expected.iter().any(|e| e == "`}`");
    let error = Error::new(
        ErrorKind::Syntax {
            expected: join_or(&expected),
            found,
        },
        Span::new(file, pos, pos + len),
    );
    // A `}` left out is found where the next declaration begins, or at the
    // end of the file: point at the brace it should close as well.
    let error = match open_brace_before(text, pos).filter(|_| wants_brace) {
        Some(open) if open + 1 < pos => {
            error.with_note(Span::new(file, open, open + 1), "this `{` is not closed")
        }
        _ => error,
    };
    // `except a b` ends the list at `a`, and `b` is read as a new task.
    match name_without_comma_after_except(text, pos) {
        Some((start, end)) => error.with_note(
            Span::new(file, start, end),
            "a `,` before this name? `except` lists its names with commas: `except a, b`",
        ),
        None => error,
    }
}

/// Where, on the line of `pos` or the line before it, a name follows
/// another after `except` with no comma between them, before `pos` (the
/// names' list ended at the first, and the second began a new
/// declaration, which then went wrong).
fn name_without_comma_after_except(text: &str, pos: usize) -> Option<(usize, usize)> {
    let pos = pos.min(text.len());
    let line_start = text[..pos].rfind('\n').map_or(0, |i| i + 1);
    missing_comma_on_line(text, line_start, pos).or_else(|| {
        let previous = text[..line_start.checked_sub(1)?]
            .rfind('\n')
            .map_or(0, |i| i + 1);
        missing_comma_on_line(text, previous, pos)
    })
}

/// [`name_without_comma_after_except`] on the line that starts at
/// `line_start`.
fn missing_comma_on_line(text: &str, line_start: usize, pos: usize) -> Option<(usize, usize)> {
    let line_end = text[line_start..]
        .find('\n')
        .map_or(text.len(), |i| line_start + i);
    // The names end at an option block or a comment.
    let line = text[line_start..line_end]
        .split(['{', '/', '"'])
        .next()
        .unwrap_or_default();
    let is_name = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let words: Vec<(usize, usize)> = (0..line.len())
        .filter(|&i| is_name(line.as_bytes()[i]) && (i == 0 || !is_name(line.as_bytes()[i - 1])))
        .map(|i| (i, line[i..].bytes().take_while(|&b| is_name(b)).count() + i))
        .collect();
    let after = words.iter().position(|&(s, e)| &line[s..e] == "except")?;
    let names = &words[after + 1..];
    names.windows(2).find_map(|pair| {
        let (gap_start, gap_end) = (pair[0].1, pair[1].0);
        let gap = &line[gap_start..gap_end];
        let missing = gap.trim().is_empty() && line_start + pair[1].0 <= pos;
        missing.then_some((line_start + pair[1].0, line_start + pair[1].1))
    })
}

/// The innermost `{` before `pos` that no `}` closes, outside comments
/// and strings.
fn open_brace_before(text: &str, pos: usize) -> Option<usize> {
    let mut open = Vec::new();
    for (i, b) in super::code::code_bytes(text).take_while(|&(i, _)| i < pos) {
        match b {
            b'{' => open.push(i),
            b'}' => {
                open.pop();
            }
            _ => {}
        }
    }
    open.pop()
}

/// Literal tokens worth naming: not comment or whitespace markers, not the
/// keywords tried only to rule them out as names.
fn is_visible_token(token: &str) -> bool {
    let internal = matches!(
        token,
        "//" | "/*" | "*/" | "\\" | "\"" | "BUILTIN_RULE" | "E" | "_"
    );
    let range = token.contains("..");
    !internal && !range && !token.trim().is_empty()
}

/// Where any top-level item may start, name one alternative for all of
/// them rather than listing every keyword.
fn collapse_item_starts(expected: &mut Vec<String>) {
    const STARTS: [&str; 14] = [
        "`let`",
        "`limits`",
        "`room`",
        "`mannequin`",
        "`profile`",
        "`base`",
        "`vision`",
        "`person`",
        "`population`",
        "`standard`",
        "`expect`",
        "`units`",
        "`use`",
        "a name",
    ];
    if !expected.iter().any(|e| e == "`room`") {
        return;
    }
    let at = expected
        .iter()
        .position(|e| STARTS.contains(&e.as_str()))
        .unwrap_or(0);
    expected.retain(|e| !STARTS.contains(&e.as_str()));
    let item = "the next declaration".to_string();
    expected.insert(at.min(expected.len()), item);
}

/// After a number, a unit or an operator may follow; name the operators
/// once, and mention units only when nothing else would do.
fn collapse_number_continuations(expected: &mut Vec<String>) {
    const UNITS: [&str; 8] = [
        "`mm`", "`cm`", "`m`", "`in`", "`deg`", "`rad`", "`arcmin`", "`%`",
    ];
    const OPERATORS: [&str; 4] = ["`+`", "`-`", "`*`", "`/`"];
    if expected.iter().any(|e| e == "an expression") {
        // What may start an expression is the expression itself.
        expected.retain(|e| !["`(`", "`-`", "`min`", "`max`"].contains(&e.as_str()));
    }
    let had_operator = expected
        .iter()
        .any(|e| OPERATORS.contains(&e.as_str()) || e == "an operator");
    expected.retain(|e| !OPERATORS.contains(&e.as_str()) && e != "an operator" && e != "`.`");
    let is_unit = |e: &String| UNITS.contains(&e.as_str()) || e == "a unit";
    if expected.iter().any(|e| !is_unit(e)) || had_operator {
        expected.retain(|e| !is_unit(e));
    }
    if had_operator && !expected.iter().any(|e| e == "an expression") {
        expected.push("an operator".to_string());
    }
}

fn push_unique(v: &mut Vec<String>, s: String) {
    if !v.contains(&s) {
        v.push(s);
    }
}

fn join_or(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} or {}", init.join(", "), last),
    }
}

/// The start and length of the last character that is not white space.
fn last_token(text: &str) -> (usize, usize) {
    text.char_indices()
        .rev()
        .find(|(_, c)| !c.is_whitespace())
        .map(|(i, c)| (i, c.len_utf8()))
        .unwrap_or((0, 0))
}

/// The token at `pos`, described, and its length in bytes.
fn found_at(text: &str, pos: usize) -> (String, usize) {
    let rest = &text[pos.min(text.len())..];
    let Some(first) = rest.chars().next() else {
        return ("end of file".to_string(), 0);
    };
    let word_len: usize = rest
        .char_indices()
        .take_while(|(_, c)| c.is_alphanumeric() || *c == '_' || *c == '.')
        .map(|(i, c)| i + c.len_utf8())
        .last()
        .unwrap_or(0);
    if word_len > 0 {
        let word: String = rest[..word_len].chars().take(40).collect();
        return (format!("`{word}`"), word_len);
    }
    let shown = match first {
        '\n' | '\r' => "end of line".to_string(),
        c => format!("`{c}`"),
    };
    (shown, first.len_utf8())
}
