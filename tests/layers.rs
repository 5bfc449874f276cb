//! Layers point one way: the layer list of ARCHITECTURE.md ("## Layers")
//! is checked against the paths in `src/`. Every top-level module is on the
//! list once; a module uses only modules of its own line or the lines
//! above; and no files use each other round a cycle. A path is any
//! `crate::`, `super::` or `self::` path (in `use` or in code), resolved to
//! the file of its longest module prefix, as `../shared/tools/import-cycles`
//! resolves them.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Which crate a file belongs to: the library or the binary.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Crate {
    Lib,
    Bin,
}

/// One source file: `rel` under `src/`, its module path, its text without
/// comments.
struct SourceFile {
    rel: String,
    module: Vec<String>,
    krate: Crate,
    code: String,
}

#[test]
fn layers_point_one_way_and_files_form_no_cycle() {
    let files = source_files();
    let layers = architecture_layers();
    let mut problems = Vec::new();
    for krate in [Crate::Lib, Crate::Bin] {
        problems.extend(listed_as_in_code(&files, &layers, krate));
    }
    let edges = file_edges(&files);
    for (from, to) in &edges {
        let (a, b) = (&files[from], &files[to]);
        let (Some(la), Some(lb)) = (layer_of(&layers, a), layer_of(&layers, b)) else {
            continue;
        };
        if lb > la {
            problems.push(format!(
                "{} (layer {}, `{}`) uses {} (layer {}, `{}`), a higher layer",
                a.rel, la, a.module[0], b.rel, lb, b.module[0]
            ));
        }
    }
    for cycle in cycles(&edges) {
        problems.push(format!("files that use each other: {}", cycle.join(" -> ")));
    }
    assert!(
        problems.is_empty(),
        "ARCHITECTURE.md's layers and src/ disagree:\n  {}",
        problems.join("\n  ")
    );
}

/// Every top-level module of `krate` is listed once, and nothing else.
fn listed_as_in_code(
    files: &BTreeMap<String, SourceFile>,
    layers: &BTreeMap<(Crate, String), usize>,
    krate: Crate,
) -> Vec<String> {
    let in_code: BTreeSet<&str> = files
        .values()
        .filter(|f| f.krate == krate && !f.module.is_empty())
        .map(|f| f.module[0].as_str())
        .collect();
    let listed: BTreeSet<&str> = layers
        .keys()
        .filter(|(k, _)| *k == krate)
        .map(|(_, m)| m.as_str())
        .collect();
    let mut problems: Vec<String> = in_code
        .difference(&listed)
        .map(|m| format!("module `{m}` ({krate:?}) is on no line of the layer list"))
        .collect();
    problems.extend(
        listed
            .difference(&in_code)
            .map(|m| format!("the layer list names `{m}` ({krate:?}), which is not in src/")),
    );
    problems
}

fn layer_of(layers: &BTreeMap<(Crate, String), usize>, file: &SourceFile) -> Option<usize> {
    let top = file.module.first()?;
    layers.get(&(file.krate, top.clone())).copied()
}

/// The numbered lines of ARCHITECTURE.md's "## Layers" section: the first
/// list is the library's, the one after "The binary" the binary's. Each
/// line names its modules in backticks before its colon.
fn architecture_layers() -> BTreeMap<(Crate, String), usize> {
    let text = std::fs::read_to_string(Path::new(ROOT).join("ARCHITECTURE.md")).unwrap();
    let section = text
        .split("\n## Layers")
        .nth(1)
        .expect("ARCHITECTURE.md has a `## Layers` section");
    let section = section.split("\n## ").next().unwrap_or(section);
    let mut layers = BTreeMap::new();
    let mut krate = Crate::Lib;
    for line in section.lines() {
        if line.starts_with("The binary") {
            krate = Crate::Bin;
        }
        let Some((number, rest)) = line.split_once(". ") else {
            continue;
        };
        let Ok(layer) = number.trim().parse::<usize>() else {
            continue;
        };
        let names = rest.split(':').next().unwrap_or_default();
        for module in names.split('`').skip(1).step_by(2) {
            let previous = layers.insert((krate, module.to_string()), layer);
            assert!(previous.is_none(), "`{module}` is listed twice");
        }
    }
    layers
}

/// Every `.rs` file under `src/`, by its path there.
fn source_files() -> BTreeMap<String, SourceFile> {
    let src = Path::new(ROOT).join("src");
    let mut paths = Vec::new();
    collect_rs(&src, &mut paths);
    let texts: BTreeMap<String, String> = paths
        .iter()
        .map(|p| {
            let rel = p
                .strip_prefix(&src)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            (rel, strip_comments(&std::fs::read_to_string(p).unwrap()))
        })
        .collect();
    let bin_modules = declared_modules(texts.get("main.rs").map_or("", String::as_str));
    texts
        .into_iter()
        .map(|(rel, code)| {
            let module = module_of(&rel);
            let krate =
                if rel == "main.rs" || module.first().is_some_and(|m| bin_modules.contains(m)) {
                    Crate::Bin
                } else {
                    Crate::Lib
                };
            let file = SourceFile {
                rel: rel.clone(),
                module,
                krate,
                code,
            };
            (rel, file)
        })
        .collect()
}

fn collect_rs(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            collect_rs(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `mod x;` declarations of a file.
fn declared_modules(code: &str) -> BTreeSet<String> {
    code.lines()
        .filter_map(|l| {
            let l = l.trim();
            let l = l.strip_prefix("pub ").unwrap_or(l);
            l.strip_prefix("mod ")?
                .strip_suffix(';')
                .map(str::to_string)
        })
        .collect()
}

/// `solvers/fabrik/mod.rs` -> `[solvers, fabrik]`; the roots are `[]`.
fn module_of(rel: &str) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .trim_end_matches(".rs")
        .split('/')
        .map(str::to_string)
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    if parts == ["lib"] || parts == ["main"] {
        parts.clear();
    }
    parts
}

/// The text without `//` and `/* */` comments (a comment may name a
/// module it does not use).
fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while !rest.is_empty() {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after.find('\n').map_or("", |i| &after[i..]);
        } else if let Some(after) = rest.strip_prefix("/*") {
            rest = after.find("*/").map_or("", |i| &after[i + 2..]);
        } else {
            let c = rest.chars().next().unwrap();
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// Which file uses which: each path of each file resolved to a file of
/// the same crate (itself and the roots left out).
fn file_edges(files: &BTreeMap<String, SourceFile>) -> BTreeSet<(String, String)> {
    let modules: BTreeMap<(Crate, Vec<String>), String> = files
        .values()
        .map(|f| ((f.krate, f.module.clone()), f.rel.clone()))
        .collect();
    let mut edges = BTreeSet::new();
    for file in files.values() {
        for path in paths_in(&file.code) {
            let Some(target) = resolve(file, &path, &modules) else {
                continue;
            };
            let is_root = target == "lib.rs" || target == "main.rs";
            if target != file.rel && !is_root {
                edges.insert((file.rel.clone(), target));
            }
        }
    }
    edges
}

/// The file that defines the longest module prefix of `path`, seen from
/// `file`.
fn resolve(
    file: &SourceFile,
    path: &[String],
    modules: &BTreeMap<(Crate, Vec<String>), String>,
) -> Option<String> {
    let (mut base, mut rest) = match path.first()?.as_str() {
        "crate" => (Vec::new(), &path[1..]),
        "self" => (file.module.clone(), &path[1..]),
        "super" => {
            let mut base = file.module.clone();
            base.pop();
            (base, &path[1..])
        }
        _ => return None,
    };
    while rest.first().is_some_and(|s| s == "super") {
        base.pop();
        rest = &rest[1..];
    }
    (0..=rest.len()).rev().find_map(|i| {
        let mut key = base.clone();
        key.extend_from_slice(&rest[..i]);
        modules.get(&(file.krate, key)).cloned()
    })
}

/// Every `crate::`, `super::` and `self::` path of `code`, `use` groups
/// (`use crate::{a, b::c}`) expanded.
fn paths_in(code: &str) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    let bytes = code.as_bytes();
    for start in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(i) = code[from..].find(start).map(|i| i + from) {
            from = i + start.len();
            let word_before =
                i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
            if word_before {
                continue;
            }
            let tail = &code[i..];
            let end = path_end(tail);
            let head: Vec<String> = tail[..end]
                .split("::")
                .filter(|s| !s.is_empty())
                .map(str::to_string)
                .collect();
            if tail[end..].starts_with('{') {
                for member in group_members(&tail[end..]) {
                    let mut path = head.clone();
                    path.extend(member.split("::").map(|s| s.trim().to_string()));
                    paths.push(path);
                }
            }
            paths.push(head);
        }
    }
    paths
}

/// Where a path of identifiers and `::` ends.
fn path_end(text: &str) -> usize {
    text.char_indices()
        .find(|&(_, c)| !(c.is_ascii_alphanumeric() || c == '_' || c == ':'))
        .map_or(text.len(), |(i, _)| i)
}

/// `{a, b::{c, d}, e as f}` -> `a`, `b::c`, `b::d`, `e`.
fn group_members(text: &str) -> Vec<String> {
    let mut depth = 0;
    let mut end = text.len();
    for (i, c) in text.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    end = i;
                    break;
                }
            }
            _ => {}
        }
    }
    let inner = &text[1..end];
    let mut members = Vec::new();
    let (mut depth, mut current) = (0, String::new());
    for c in inner.chars().chain([',']) {
        match c {
            '{' => {
                depth += 1;
                current.push(c);
            }
            '}' => {
                depth -= 1;
                current.push(c);
            }
            ',' if depth == 0 => {
                let member = current
                    .trim()
                    .split(" as ")
                    .next()
                    .unwrap_or("")
                    .trim()
                    .to_string();
                if let Some(brace) = member.find('{') {
                    let prefix = member[..brace].trim_end_matches("::").to_string();
                    for sub in group_members(&member[brace..]) {
                        members.push(format!("{prefix}::{sub}"));
                    }
                } else if !member.is_empty() {
                    members.push(member);
                }
                current.clear();
            }
            _ => current.push(c),
        }
    }
    members
}

/// The cycles of the file graph (strongly connected components of more
/// than one file), each as a path of files.
fn cycles(edges: &BTreeSet<(String, String)>) -> Vec<Vec<String>> {
    let mut next: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (a, b) in edges {
        next.entry(a).or_default().push(b);
    }
    let nodes: BTreeSet<&str> = edges
        .iter()
        .flat_map(|(a, b)| [a.as_str(), b.as_str()])
        .collect();
    let reaches = |from: &str| -> BTreeSet<&str> {
        let mut seen = BTreeSet::new();
        let mut stack = vec![from];
        while let Some(n) = stack.pop() {
            for &m in next.get(n).map_or(&[][..], Vec::as_slice) {
                if seen.insert(m) {
                    stack.push(m);
                }
            }
        }
        seen
    };
    let reach: BTreeMap<&str, BTreeSet<&str>> = nodes.iter().map(|&n| (n, reaches(n))).collect();
    let mut done = BTreeSet::new();
    let mut found = Vec::new();
    for &n in &nodes {
        if done.contains(n) || !reach[n].contains(n) {
            continue;
        }
        let component: Vec<String> = nodes
            .iter()
            .filter(|&&m| reach[n].contains(m) && reach[m].contains(n))
            .map(|m| m.to_string())
            .collect();
        done.extend(
            component
                .iter()
                .map(|m| nodes.get(m.as_str()).copied().unwrap()),
        );
        found.push(component);
    }
    found
}

/// ARCHITECTURE.md, "Invariants": a solver answers "from these starts,
/// reach this target on this chain" through the plugin SDK; it names no
/// meter, cache, engine, task, base or scenario.
#[test]
fn solvers_name_the_plugin_sdk_and_geometry_only() {
    const ALLOWED: [&str; 8] = [
        "solvers",
        "plugin",
        "allowance",
        "kinematics",
        "geometry",
        "collision",
        "scene",
        "options",
    ];
    let files = source_files();
    let problems: Vec<String> = file_edges(&files)
        .iter()
        .filter(|(from, _)| from.starts_with("solvers/"))
        .filter(|(_, to)| !ALLOWED.contains(&files[to].module[0].as_str()))
        .map(|(from, to)| format!("{from} uses {to}"))
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// ARCHITECTURE.md, "Invariants": the plugin traits and the solvers know
/// a run only as the `Allowance` they spend from: no file of `plugin/` or
/// `solvers/` uses the meter (`crate::meter`, `Meter`) or names it in code.
#[test]
fn plugins_and_solvers_know_an_allowance_not_the_meter() {
    let files = source_files();
    let problems: Vec<String> = files
        .values()
        .filter(|f| f.rel.starts_with("plugin/") || f.rel.starts_with("solvers/"))
        .filter(|f| {
            let code = f.code.to_lowercase();
            code.split(|c: char| !c.is_alphanumeric() && c != '_')
                .any(|word| word == "meter")
        })
        .map(|f| format!("{} names the meter", f.rel))
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// ARCHITECTURE.md, "Invariants": every `static` of the library, each
/// with what it holds (immutable tables and locks), and no
/// `thread_local!`. A new static is listed here, with why it may not be
/// owned by a run or a watch session instead.
#[test]
fn every_static_is_listed_with_what_it_holds() {
    const LISTED: [(&str, &str, &str); 5] = [
        ("ansur.rs", "SURVEY", "immutable: the survey's rows"),
        ("syntax/parser.rs", "PRATT", "immutable: the operator table"),
        (
            "syntax/parser.rs",
            "ERROR_DETAIL",
            "a lock around pest's process-wide setting",
        ),
        ("meter.rs", "UNMETERED", "immutable: the meter of no run"),
        (
            "output/files.rs",
            "WRITING",
            "a lock: one --out set written at a time",
        ),
    ];
    let files = source_files();
    let mut found = BTreeSet::new();
    // Unit tests' files (`*_tests.rs`) may keep what they like.
    let lib = files.values().filter(|f| f.krate == Crate::Lib);
    for file in lib.filter(|f| !f.rel.ends_with("_tests.rs")) {
        for (k, _) in file.code.match_indices("static ") {
            let name: String = file.code[k + 7..]
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() && name.chars().all(|c| !c.is_ascii_lowercase()) {
                found.insert((file.rel.clone(), name));
            }
        }
    }
    // A thread-local would hold what runs on a thread: a run's or a
    // solve's state, which belongs to the run (or is passed to the solve).
    let locals: Vec<&str> = (files.values())
        .filter(|f| f.krate == Crate::Lib && !f.rel.ends_with("_tests.rs"))
        .filter(|f| f.code.contains("thread_local!"))
        .map(|f| f.rel.as_str())
        .collect();
    assert!(locals.is_empty(), "thread-locals in {locals:?}");
    let listed: BTreeSet<(String, String)> = LISTED
        .iter()
        .map(|(file, name, _)| (file.to_string(), name.to_string()))
        .collect();
    let new: Vec<_> = found.difference(&listed).collect();
    let gone: Vec<_> = listed.difference(&found).collect();
    assert!(
        new.is_empty() && gone.is_empty(),
        "statics not listed: {new:?}; listed but gone: {gone:?}"
    );
}

/// ARCHITECTURE.md, "Invariants": `lib.rs` exports the run API and the
/// plugin SDK and nothing else; every other module is private, public
/// (and hidden) only with the `internals` feature that the crate's own
/// tests, benches and fuzz targets turn on. A new export is added here
/// with the reason it belongs to a program that uses the library.
#[test]
fn the_library_exports_the_run_api_and_the_plugin_sdk_only() {
    const EXPORTED: [&str; 23] = [
        // What a run takes and gives, and the plugin SDK.
        "pub mod limits;",
        "pub mod machine_diagnostics;",
        "pub mod output;",
        "pub mod plugin;",
        "pub mod progress;",
        "pub mod report;",
        "pub mod suite;",
        // What an editor asks of a scenario: `reach lsp` is its client.
        "pub mod editor;",
        // Watch mode's cache of answers, as the binary keeps one.
        "pub use cache::{CacheStats, Plan, TaskCache};",
        "pub use error::{Diagnostics, Error, ErrorKind};",
        "pub use escape::escaped;",
        "pub use kept::Memo;",
        "pub use limits::Limits;",
        "pub use loader::Input;",
        "pub use machine_diagnostics::{DiagnosticStyle, Finding};",
        "pub use read::read_root;",
        "pub use scenario::{fingerprint, read_shard, write_shard};",
        "pub use scenario::{PeopleBuilt, Scenario, ShardOf, ShardPart};",
        "pub use source::Sources;",
        "pub use std_modules::listing as stdlib_listing;",
        "pub use stdlib::describe as stdlib_entry;",
        "pub struct Session<'a> {",
        "pub struct Ran {",
    ];
    let text = std::fs::read_to_string(Path::new(ROOT).join("src/lib.rs")).unwrap();
    let exported: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("pub ") && !l.starts_with("pub fn "))
        .collect();
    let mut expected = EXPORTED.to_vec();
    expected.sort_unstable();
    let mut found = exported.clone();
    found.sort_unstable();
    assert_eq!(found, expected, "lib.rs's exports");
    let functions: Vec<&str> = text.lines().filter(|l| l.starts_with("pub fn ")).collect();
    assert_eq!(
        functions.len(),
        2,
        "reach::check and reach::run: {functions:?}"
    );
    // The other modules are declared only through `internal_modules!`.
    assert!(
        text.lines()
            .all(|l| !l.starts_with("mod ") && !l.starts_with("pub(crate) mod")),
        "a module declared outside internal_modules!"
    );
    assert!(text.contains("#[cfg(not(feature = \"internals\"))]\n            mod $module;"));
}

/// The example of a plugin written with the library
/// (`examples/custom_solver.rs`) names only the run API and the plugin SDK:
/// what a program outside the crate can.
#[test]
fn the_custom_solver_example_needs_no_internals() {
    let text = std::fs::read_to_string(Path::new(ROOT).join("examples/custom_solver.rs")).unwrap();
    let public = [
        "plugin",
        "report",
        "output",
        "suite",
        "limits",
        "progress",
        "machine_diagnostics",
    ];
    let internal: Vec<&str> = text
        .match_indices("reach::")
        .filter_map(|(k, _)| {
            let rest = &text[k + 7..];
            let name_end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))?;
            let name = &rest[..name_end];
            let is_module = rest[name_end..].starts_with("::");
            (is_module && !public.contains(&name)).then_some(name)
        })
        .collect();
    assert!(internal.is_empty(), "internal modules named: {internal:?}");
}
