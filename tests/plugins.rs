//! A solver registered by a program, named in a scenario like a built-in one
//! (the code is `examples/custom_solver.rs`, run here as a test).

#[path = "../examples/custom_solver.rs"]
mod custom_solver;

use reach::plugin::{PluginKind, Registry};
use reach::report::TaskReport;

#[test]
fn a_registered_solver_is_usable_by_name() {
    let report = custom_solver::run_scenario();
    let solvers: Vec<&str> = report
        .tasks
        .iter()
        .filter_map(|t| match t {
            TaskReport::Reach(r) => Some(r.solver.as_str()),
            _ => None,
        })
        .collect();
    assert_eq!(solvers, ["sampling", "incremental"]);
    for task in &report.tasks {
        let TaskReport::Reach(r) = task else { continue };
        assert!(r.ok, "{} did not reach: {} mm", r.solver, r.distance_mm);
    }
}

#[test]
fn registering_adds_to_the_listing_and_validates_options() {
    let mut registry = Registry::builtin();
    registry.register_solver(custom_solver::Sampling);
    assert_eq!(
        registry.names(PluginKind::Solver),
        ["incremental", "dls", "fabrik", "sampling"]
    );
    let text = custom_solver::SCENARIO.replace("samples 100000", "sample 100000");
    let (_, checked) = reach::check(
        reach::Input::Text {
            name: "t.reach",
            text: &text,
        },
        &registry,
    );
    let message = checked.unwrap_err().errors[0].kind().to_string();
    assert_eq!(message, "solver `sampling` has no option `sample`");
}

#[test]
fn every_plugin_builds_from_its_declared_defaults() {
    use reach::plugin::{Options, ParamKind, ParamSpec, Value};
    use reach::report::Report;
    // Options at their defaults; a required one (a fixed base's `at`, an
    // advice's `from` and `to`) gets a value of its kind. Every plugin
    // must build from them without an error.
    let fill = |params: Vec<ParamSpec>| {
        let mut o = Options::defaults(&params);
        for p in params.iter().filter(|p| p.default.is_none() && !p.optional) {
            let value = match p.kind {
                ParamKind::Length => Value::Length(1000.0),
                _ => Value::Point(Default::default()),
            };
            o = o.set(p.name, value);
        }
        o
    };
    let registry = Registry::builtin();
    for name in registry.names(PluginKind::Solver) {
        let p = registry.solver(name).unwrap();
        if let Err(e) = p.build(&fill(p.params())) {
            panic!("solver {name}: {e}");
        }
    }
    let physique = physique();
    for name in registry.names(PluginKind::Base) {
        let p = registry.base(name).unwrap();
        if let Err(e) = p.build(&fill(p.params()), &physique) {
            panic!("base {name}: {e}");
        }
    }
    for name in registry.names(PluginKind::Task) {
        let p = registry.task(name).unwrap();
        if let Err(e) = p.configure(&fill(p.params()), &registry) {
            panic!("task {name}: {e}");
        }
    }
    for name in registry.names(PluginKind::Format) {
        let p = registry.format(name).unwrap();
        let empty = Report {
            schema: 1,
            file: "x".into(),
            notes: Vec::new(),
            tasks: Vec::new(),
            expectations: Vec::new(),
            advised_together: Vec::new(),
        };
        let scene = reach::plugin::FormatScene::empty();
        let text = p.render(&empty, &scene);
        assert_eq!(text.is_some(), p.prints(), "format `{name}`");
        // A format that prints writes a file of any report too.
        let files = p.files(&empty, &scene);
        assert!(!p.prints() || !files.is_empty(), "format `{name}`");
    }
}

/// The body of `std::arm`'s mannequin, legs and all, as a base sees it.
fn physique() -> reach::scene::Physique {
    let body = reach::stdlib::body("arm", "right_arm").expect("std::arm checks");
    reach::scene::Physique::of(&body)
}

#[test]
fn options_built_by_hand_that_miss_a_value_are_an_error_not_a_panic() {
    use reach::plugin::{Options, Value};
    let registry = Registry::builtin();
    let fixed = registry.base("fixed").unwrap();
    let missing = fixed
        .build(&Options::default(), &physique())
        .err()
        .expect("`at` is required");
    assert_eq!(missing.to_string(), "option `at` must be given");
    let params = fixed.params();
    let at = params.iter().find(|p| p.name == "at").unwrap().name;
    let wrong = Options::default().set(at, Value::Length(1.0));
    let wrong = fixed
        .build(&wrong, &physique())
        .err()
        .expect("`at` is a point");
    assert_eq!(wrong.to_string(), "option `at` must be a point (x, y, z)");
}
