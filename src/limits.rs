//! Bounds on what one scenario may ask of the tool, so that hostile or
//! broken input gets a diagnostic instead of exhausting the stack, the
//! memory or the user's afternoon. Each is an option of the command line
//! (`reach run --max-solves N`, ...) and a field of [`Limits`] for
//! programs; each has a ceiling, the largest value the tool has been tested
//! to handle without exhausting its stack. Documented in docs/language.md.

/// The bounds a scenario is checked against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Largest file read (scenario, OBJ mesh, URDF), in bytes.
    pub file_bytes: u64,
    /// Largest scenario file (`.reach`, the root or a used one), in bytes:
    /// smaller than a mesh may be, since its text is parsed (about 5 MB a
    /// second).
    pub scenario_bytes: u64,
    /// Most boxes and meshes in one room (where they crowd, the floor a base may
    /// stand on costs more than their count).
    pub boxes: usize,
    /// Deepest nesting of parentheses and braces (expressions, points,
    /// option blocks), counted together.
    pub nesting: usize,
    /// Most operands and operators in one expression, those inside its
    /// parentheses included (each is a step of a recursion).
    pub expression_terms: usize,
    /// Longest chain of constants defined in terms of each other.
    pub constant_chain: usize,
    /// Longest chain of files using each other.
    pub use_chain: usize,
    /// Longest chain of mannequins naming each other (`a = b(...)`).
    pub alias_chain: usize,
    /// Most solver starts the tasks of a scenario may need, counted at
    /// their worst (every placement tried, every retry run), each weighted
    /// by its solver's iteration options over their defaults.
    pub solver_starts: u64,
    /// Most work the solvers of one run may do, in the units of
    /// solver work (about a joint moved once), with the routes from
    /// the rooms' doors: counted as they work, and the run stopped with a
    /// diagnostic once past it.
    pub solver_work: u64,
    /// Most people one population may draw, and most `person`s a
    /// scenario declares (each is built, about 16 KB, before any task).
    pub people: usize,
    /// Most triangles all the meshes of a scenario may hold, each mesh
    /// declared counted, a glTF's instances placed (a small file may place
    /// one mesh millions of times; a triangle takes about 230 bytes once
    /// its tree is built).
    pub triangles: usize,
    /// Most joints in one mannequin, declared in the scenario or the chain
    /// of a URDF from root to tip (each posture check pairs a chain's
    /// solids with each other: quadratic in the joints).
    pub joints: usize,
    /// Most points the tasks of one run answer together: each point of a
    /// map once for each person (a population's map once), a reach or gaze
    /// one. Each point's answer is held in the report and written to
    /// several files (JSON, HTML, a map's CSV and SVG), all in memory
    /// until the set is written.
    pub map_points: u64,
    /// How many times these bounds a scenario may raise its own bounds on
    /// solver starts and work to (`limits { ... }` in the file it runs):
    /// a file from elsewhere runs for hours only where the user says so.
    pub raise: u64,
}

/// The limits unless told otherwise: far beyond any real scenario.
pub const DEFAULTS: Limits = Limits {
    file_bytes: 64 * 1024 * 1024,
    scenario_bytes: 16 * 1024 * 1024,
    boxes: 5_000,
    nesting: 64,
    expression_terms: 1024,
    constant_chain: 256,
    use_chain: 64,
    alias_chain: 16,
    solver_starts: 20_000_000,
    solver_work: 250_000_000,
    people: 10_000,
    triangles: 2_000_000,
    joints: 2_000,
    map_points: 1_000_000,
    raise: 10,
};

impl Default for Limits {
    fn default() -> Self {
        DEFAULTS
    }
}

/// The largest value each limit may be raised to: the command line parses
/// on a 64 MiB stack, and tests/cli.rs checks input at every ceiling there
/// (a program calling [`crate::Session`] on a smaller stack should
/// keep to the defaults).
pub const CEILINGS: Limits = Limits {
    file_bytes: 1 << 30,
    scenario_bytes: 1 << 30,
    boxes: 1_000_000,
    nesting: 256,
    expression_terms: 10_000,
    constant_chain: 4096,
    use_chain: 1024,
    alias_chain: 256,
    solver_starts: 1_000_000_000_000,
    solver_work: 1_000_000_000_000_000,
    people: 1_000_000,
    triangles: 50_000_000,
    joints: 100_000,
    map_points: 20_000_000,
    raise: 1_000_000,
};
