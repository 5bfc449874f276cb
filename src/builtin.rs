//! The registry of built-in plugins: every solver, base, task, output
//! format and standard the crate has, by name. It sits above the plugins it names (the
//! plugin layer itself knows none of them).

use crate::plugin::Registry;

impl Registry {
    /// The built-in plugins.
    pub fn builtin() -> Self {
        let mut r = Registry::default();
        r.register_solver(crate::solvers::Incremental);
        r.register_solver(crate::solvers::Dls);
        r.register_solver(crate::solvers::Fabrik);
        r.register_base(crate::bases::Fixed);
        r.register_base(crate::bases::Trolley);
        r.register_base(crate::bases::Wheelchair);
        r.register_task(crate::tasks::Reach);
        r.register_task(crate::tasks::Gaze);
        r.register_task(crate::tasks::ReachAndGaze);
        r.register_task(crate::tasks::Map);
        r.register_task(crate::tasks::GazeMap);
        r.register_task(crate::tasks::Advise);
        r.register_format(crate::output::Text);
        r.register_format(crate::output::Json);
        r.register_format(crate::output::Html);
        r.register_format(crate::output::GlbFile);
        r.register_format(crate::output::Maps);
        r.register_format(crate::output::AdviceFiles);
        r.register_standard(crate::standards::Ada2010);
        r
    }
}
