//! What a place in a scenario is, in Markdown, for an editor's hover: a
//! name's declaration and what the check made of it (a target's place in
//! its room, a box's corner and size, a person's body joint by joint and
//! base with every option, a population's people; a standard library
//! declaration as `reach stdlib NAME` describes it, with the sources of
//! its figures), a plugin's or an option's doc, a number's value in mm or
//! deg.

use super::outline::{Found, OptionOwner, Outline, Symbol, SymbolKind};
use crate::options::{ParamSpec, PluginKind, Settings};
use crate::plugin::Registry;
use crate::scenario::Scenario;
use crate::source::Sources;
use crate::span::FileId;
use crate::syntax::ast::UseTarget;
use crate::units::{Dim, Quantity, Unit};

/// What hover shows at byte `offset` of file `file` (its index in
/// `sources`; none where the place is nothing it knows).
pub fn hover(
    (sources, file, offset): (&Sources, usize, usize),
    outline: Option<&Outline>,
    scenario: Option<&Scenario>,
    registry: &Registry,
) -> Option<String> {
    let file = FileId(u32::try_from(file).ok()?);
    if file.0 as usize >= sources.len() {
        return None;
    }
    let text = sources.get(file).text.as_str();
    if let Some(number) = number_at(text, offset) {
        return Some(number);
    }
    let found = outline?.at(file, offset)?;
    let about = About {
        sources,
        scenario,
        registry,
    };
    match found {
        Found::Declaration(symbol) => Some(about.symbol(symbol)),
        Found::Use(reference, symbols) => match symbols.as_slice() {
            // Not declared: a standard library name the file does not
            // use, or a word the option takes (`along z`).
            [] => std_declaration(&reference.name, reference.kinds),
            found => Some(
                found
                    .iter()
                    .map(|s| about.symbol(s))
                    .collect::<Vec<_>>()
                    .join("\n\n---\n\n"),
            ),
        },
        Found::Plugin(p) => about.plugin(p.kind, &p.name),
        Found::Option(o) => about.option(&o.owner, &o.name),
        Found::Module(u) => Some(match &u.target {
            UseTarget::Std(module) => {
                crate::std_modules::entry(module, crate::std_texts::module(module)?)
            }
            UseTarget::Path(path) => format!("`{path}`: read from the directory of this file"),
        }),
    }
}

/// A standard library declaration of one of `kinds` named `name`, as
/// `reach stdlib NAME` describes it.
fn std_declaration(name: &str, kinds: &[SymbolKind]) -> Option<String> {
    let described = kinds.iter().any(|k| {
        matches!(
            k,
            SymbolKind::Mannequin
                | SymbolKind::Profile
                | SymbolKind::BasePreset
                | SymbolKind::VisionPreset
                | SymbolKind::Population
        )
    });
    if !described {
        return None;
    }
    crate::stdlib::describe(name)
        .ok()
        .map(|text| format!("```text\n{text}```"))
}

struct About<'a> {
    sources: &'a Sources,
    scenario: Option<&'a Scenario>,
    registry: &'a Registry,
}

impl About<'_> {
    fn symbol(&self, symbol: &Symbol) -> String {
        let source = self.sources.get(symbol.span.file);
        let text = source.text.as_str();
        let whole = text
            .get(symbol.whole.start as usize..symbol.whole.end as usize)
            .unwrap_or_default();
        let first_line = whole.lines().next().unwrap_or_default();
        let line = source.line_column(symbol.span.start as usize).0;
        let within = symbol
            .container
            .as_ref()
            .map(|c| format!(" in `{c}`"))
            .unwrap_or_default();
        let mut out = format!(
            "```reach\n{first_line}\n```\n{} `{}`{within}, {}:{line}",
            symbol.kind.word(),
            symbol.name,
            source.name
        );
        if let Some(values) = self.values(symbol) {
            out.push_str("\n\n");
            out.push_str(&values);
        }
        out
    }

    /// What the check made of the declaration, where it checked.
    fn values(&self, symbol: &Symbol) -> Option<String> {
        if let Some(std) = self.std_entry(symbol) {
            return Some(std);
        }
        let scenario = self.scenario?;
        let room = || {
            let name = symbol.container.as_deref()?;
            scenario.rooms.iter().find(|r| r.name == name)
        };
        match symbol.kind {
            SymbolKind::Room => {
                let room = scenario.rooms.iter().find(|r| r.name == symbol.name)?;
                Some(format!(
                    "{} x {} x {} mm; {} boxes, {} meshes, {} targets, {} surfaces, {} doors",
                    mm(room.size_mm.x),
                    mm(room.size_mm.y),
                    mm(room.size_mm.z),
                    room.boxes.len(),
                    room.meshes.len(),
                    room.targets.len(),
                    room.surfaces.len(),
                    room.doors.len()
                ))
            }
            SymbolKind::Target => {
                let target = room()?.targets.iter().find(|t| t.name == symbol.name)?;
                let p = target.position_mm;
                Some(format!(
                    "at ({}, {}, {}) mm in the room",
                    mm(p.x),
                    mm(p.y),
                    mm(p.z)
                ))
            }
            SymbolKind::Box => {
                let b = room()?.boxes.iter().find(|b| b.name == symbol.name)?;
                let (c, s) = (b.corner_mm, b.size_mm);
                Some(format!(
                    "corner ({}, {}, {}) mm, size {} x {} x {} mm, top at {} mm{}",
                    mm(c.x),
                    mm(c.y),
                    mm(c.z),
                    mm(s.x),
                    mm(s.y),
                    mm(s.z),
                    mm(c.z + s.z),
                    if b.yaw_rad != 0.0 {
                        format!(", turned {} deg", mm(b.yaw_rad.to_degrees()))
                    } else {
                        String::new()
                    }
                ))
            }
            SymbolKind::Door => {
                let door = room()?.doors.iter().find(|d| d.name == symbol.name)?;
                use crate::scene::Wall;
                let (wall, along) = match door.wall {
                    Wall::XMin => ("x = 0", "y"),
                    Wall::XMax => ("x = the room's length", "y"),
                    Wall::YMin => ("y = 0", "x"),
                    _ => ("y = the room's width", "x"),
                };
                Some(format!(
                    "in the wall {wall}, its middle at {along} = {} mm, {} mm wide",
                    mm(door.along_mm),
                    mm(door.width_mm)
                ))
            }
            SymbolKind::Surface => {
                let surface = room()?.surfaces.iter().find(|s| s.name == symbol.name)?;
                let (c, u, v) = (surface.corner_mm, surface.u_mm, surface.v_mm);
                Some(format!(
                    "corner ({}, {}, {}) mm, {} x {} mm",
                    mm(c.x),
                    mm(c.y),
                    mm(c.z),
                    mm(u.norm()),
                    mm(v.norm())
                ))
            }
            SymbolKind::Constant => {
                let mut constants = scenario.constants.iter();
                let (_, value) = constants.find(|(n, _)| *n == symbol.name)?;
                Some(format!("= {}", quantity(value)))
            }
            SymbolKind::Person => self.person(scenario, &symbol.name),
            SymbolKind::Population => self.population(scenario, &symbol.name),
            SymbolKind::BasePreset => self.base_preset(symbol),
            _ => None,
        }
    }

    /// A declaration of the standard library's: its entry of `reach
    /// stdlib`.
    fn std_entry(&self, symbol: &Symbol) -> Option<String> {
        // Only where it is declared in a module of the library.
        self.sources.get(symbol.span.file).std_module()?;
        let entry = crate::stdlib::describe(&symbol.name).ok()?;
        Some(format!("```text\n{entry}```"))
    }

    fn person(&self, scenario: &Scenario, name: &str) -> Option<String> {
        let person = scenario.persons.iter().find(|p| p.name == name)?;
        let mut out = format!("mannequin `{}`", person.mannequin);
        if crate::std_texts::home_of("mannequin", &person.mannequin).is_some() {
            out.push_str(&format!(
                " (the standard library's: `reach stdlib {}` gives the sources of its figures)",
                person.mannequin
            ));
        }
        out.push_str(&format!("; base `{}`", person.base.name));
        let options: Vec<String> = (person.base.options.iter())
            .map(|(k, v)| format!("{k} {}", v.display()))
            .collect();
        if !options.is_empty() {
            out.push_str(&format!(" {{ {} }}", options.join(", ")));
        }
        if let Some((_, stature)) = person.measures.iter().find(|(n, _)| n == "stature") {
            out.push_str(&format!("\n\nstature {}", quantity(stature)));
        }
        if !person.measures.is_empty() {
            let measures: Vec<String> = (person.measures.iter())
                .map(|(name, value)| format!("{name} {}", quantity(value)))
                .collect();
            out.push_str(&format!("\n\nbuilt from: {}", measures.join(", ")));
        }
        out.push_str("\n\n```text\n");
        out.push_str(&crate::stdlib::body_table(&person.body));
        out.push_str("```");
        Some(out)
    }

    fn population(&self, scenario: &Scenario, name: &str) -> Option<String> {
        let population = scenario.populations.iter().find(|p| p.name == name)?;
        let drawn = &population.drawn;
        let women = drawn.iter().filter(|d| d.female).count();
        let statures: Vec<f64> = drawn.iter().map(|d| d.stature_mm).collect();
        let least = statures.iter().copied().fold(f64::INFINITY, f64::min);
        let most = statures.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let first = scenario.persons.get(population.members.start)?;
        Some(format!(
            "{} people drawn from ANSUR II (seed {}), {women} women; statures {} to {} mm; \
             mannequin `{}`, base `{}`",
            drawn.len(),
            population.seed,
            mm(least),
            mm(most),
            first.mannequin,
            first.base.name
        ))
    }

    /// A preset's options, each given or at its plugin's default.
    fn base_preset(&self, symbol: &Symbol) -> Option<String> {
        let scenario = self.scenario?;
        let person = scenario.persons.iter().find(|p| {
            let source = self.sources.get(symbol.span.file);
            let declared = &source.text[symbol.whole.start as usize..symbol.whole.end as usize];
            declared.contains(&format!("= {}", p.base.name))
        });
        let plugin = person.map(|p| p.base.name.clone())?;
        let params = self.registry.params(PluginKind::Base, &plugin)?;
        Some(options_table(&params))
    }

    fn plugin(&self, kind: PluginKind, name: &str) -> Option<String> {
        let plugin = (self.registry.of_kind(kind).into_iter()).find(|p| p.name() == name)?;
        let mut out = format!("{} plugin `{name}`: {}", kind.noun(), plugin.doc());
        let params = plugin.params();
        if !params.is_empty() {
            out.push_str("\n\n");
            out.push_str(&options_table(&params));
        }
        Some(out)
    }

    fn option(&self, owner: &OptionOwner, name: &str) -> Option<String> {
        let (params, whose) = match owner {
            OptionOwner::Plugin(kind, plugin) => (
                self.registry.params(*kind, plugin)?,
                format!("{} `{plugin}`", kind.noun()),
            ),
            OptionOwner::Vision => (crate::scene::Vision::params(), "`vision`".into()),
            OptionOwner::Limits => (crate::check::limits_params(), "`limits`".into()),
        };
        let param = params.iter().find(|p| p.name == name)?;
        Some(format!(
            "option `{name}` of {whose}\n\n{}",
            option_line(param)
        ))
    }
}

/// Each option: its kind, its default, its doc.
fn options_table(params: &[ParamSpec]) -> String {
    let rows: Vec<String> = params
        .iter()
        .map(|p| format!("- `{}`: {}", p.name, option_line(p)))
        .collect();
    rows.join("\n")
}

fn option_line(param: &ParamSpec) -> String {
    let default = param.default_words();
    format!("{} ({default}): {}", param.kind.describe(), param.doc)
}

/// A value with its unit: a length in mm, an angle in deg, to 0.1.
fn quantity(value: &Quantity) -> String {
    match *value {
        Quantity::Dimensioned { value, dim } if dim == Dim::LENGTH => format!("{} mm", mm(value)),
        Quantity::Dimensioned { value, dim } if dim == Dim::ANGLE => {
            format!("{} deg", mm(value.to_degrees()))
        }
        Quantity::Dimensioned { value, dim } if dim == Dim::NONE => trimmed(value),
        Quantity::Dimensioned { value, dim } => format!("{} ({dim})", trimmed(value)),
        Quantity::Bare { value, defaults } => {
            let length = value * defaults.length.to_internal();
            let angle = (value * defaults.angle.to_internal()).to_degrees();
            format!(
                "{} (no unit: {} mm as a length, {} deg as an angle)",
                trimmed(value),
                mm(length),
                mm(angle)
            )
        }
    }
}

/// A length or an angle as hover shows it: to 0.1, without a trailing
/// `.0`.
fn mm(value: f64) -> String {
    let rounded = (value * 10.0).round() / 10.0;
    if rounded == rounded.trunc() {
        format!("{}", rounded as i64)
    } else {
        format!("{rounded:.1}")
    }
}

/// A number written at `offset` (in code, not a comment), with its unit:
/// what it is in mm or deg (or, bare, what the file's `units` make it
/// where a length or an angle is meant).
fn number_at(text: &str, offset: usize) -> Option<String> {
    let bytes = text.as_bytes();
    let is_part = |b: u8| b.is_ascii_alphanumeric() || b == b'.' || b == b'_';
    let mut start = offset.min(text.len());
    while start > 0 && is_part(bytes[start - 1]) {
        start -= 1;
    }
    let mut end = offset.min(text.len());
    while end < bytes.len() && is_part(bytes[end]) {
        end += 1;
    }
    // An exponent's sign is in the number: `1e-3m`, from either side.
    let exponent_sign = |k: usize| {
        matches!(bytes.get(k), Some(b'+' | b'-'))
            && k >= 2
            && matches!(bytes[k - 1], b'e' | b'E')
            && bytes[k - 2].is_ascii_digit()
    };
    if start >= 1 && exponent_sign(start - 1) {
        start -= 1;
        while start > 0 && is_part(bytes[start - 1]) {
            start -= 1;
        }
    }
    if exponent_sign(end) {
        end += 1;
        while end < bytes.len() && is_part(bytes[end]) {
            end += 1;
        }
    }
    let token = text.get(start..end)?;
    if !token.starts_with(|c: char| c.is_ascii_digit()) || !is_code(text, start) {
        return None;
    }
    let digits_end = number_end(token);
    let negative = text[..start].ends_with('-')
        && !text[..start - 1]
            .trim_end()
            .ends_with(|c: char| c.is_ascii_alphanumeric() || c == ')');
    let sign = if negative { -1.0 } else { 1.0 };
    let value = sign * token[..digits_end].parse::<f64>().ok()?;
    let written = if negative {
        format!("-{token}")
    } else {
        token.to_string()
    };
    let mut unit_text = &token[digits_end..];
    if unit_text.is_empty() && text[end..].trim_start_matches([' ', '\t']).starts_with('%') {
        unit_text = "%";
    }
    if unit_text.is_empty() {
        let (length, angle) = file_units(text);
        let as_length = value * length.to_internal();
        let as_angle = (value * angle.to_internal()).to_degrees();
        return Some(format!(
            "`{written}`: a number without unit ({}). A count or a factor is that number; where a \
             length is meant it is in the file's `units`, {} {} = {} mm; where an angle is, {} {} = {} deg",
            trimmed(value),
            trimmed(value),
            length.symbol(),
            mm(as_length),
            trimmed(value),
            angle.symbol(),
            trimmed(as_angle),
        ));
    }
    let unit = match unit_text {
        "%" => Unit::Percent,
        other => Unit::parse(other)?,
    };
    let internal = value * unit.to_internal();
    Some(match unit {
        Unit::Percent => format!("`{written}`: a share, {}", trimmed(internal)),
        u if u.is_length() => format!("`{written}` = {} mm", mm(internal)),
        _ => format!("`{written}` = {} deg", trimmed(internal.to_degrees())),
    })
}

/// Whether byte `at` of `text` is code (not in a comment or a string).
fn is_code(text: &str, at: usize) -> bool {
    crate::syntax::code_bytes(text).any(|(k, _)| k == at)
}

/// Where a number's digits (and decimals, and exponent) end.
fn number_end(token: &str) -> usize {
    let bytes = token.as_bytes();
    let mut k = bytes
        .iter()
        .take_while(|b| b.is_ascii_digit() || **b == b'.')
        .count();
    if matches!(bytes.get(k), Some(b'e' | b'E')) {
        let mut j = k + 1;
        if matches!(bytes.get(j), Some(b'+' | b'-')) {
            j += 1;
        }
        if bytes.get(j).is_some_and(u8::is_ascii_digit) {
            k = j + bytes[j..].iter().take_while(|b| b.is_ascii_digit()).count();
        }
    }
    k
}

fn trimmed(value: f64) -> String {
    let text = format!("{value:.4}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The file's default units for a length and an angle (mm and deg where
/// it says nothing).
fn file_units(text: &str) -> (Unit, Unit) {
    let mut length = Unit::Mm;
    let mut angle = Unit::Deg;
    for line in text.lines() {
        let Some(rest) = line.trim().strip_prefix("units ") else {
            continue;
        };
        for word in rest.split_whitespace() {
            match Unit::parse(word) {
                Some(u) if u.is_length() => length = u,
                Some(u @ (Unit::Deg | Unit::Rad)) => angle = u,
                _ => {}
            }
        }
    }
    (length, angle)
}
