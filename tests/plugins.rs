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
    let text = custom_solver::SCENARIO.replace("samples 20000", "sample 20000");
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
    use reach::plugin::{Options, ParamSpec, Value};
    use reach::report::Report;
    // A plugin must read only options it declares; required ones get a value.
    let fill = |params: Vec<ParamSpec>| {
        let mut o = Options::defaults(&params);
        for p in params.iter().filter(|p| p.default.is_none()) {
            o = Options::new(
                o.iter()
                    .cloned()
                    .chain([(p.name, Value::Point(Default::default()))])
                    .collect(),
            );
        }
        o
    };
    let registry = Registry::builtin();
    for name in registry.names(PluginKind::Solver) {
        let p = registry.solver(name).unwrap();
        p.build(&fill(p.params()));
    }
    for name in registry.names(PluginKind::Base) {
        let p = registry.base(name).unwrap();
        p.build(&fill(p.params()));
    }
    for name in registry.names(PluginKind::Format) {
        let p = registry.format(name).unwrap();
        p.render(&Report {
            schema: 1,
            file: "x".into(),
            tasks: Vec::new(),
        });
    }
}
