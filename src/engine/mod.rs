//! The engine: what a run and a watch session keep around the plugins'
//! plain questions: the solves kept from a task's last run for its next
//! (`kept_solves.rs`, with the fingerprint a solver is kept by) and the
//! proofs that a point is out of reach kept for a whole map
//! (`kept_proofs.rs`). Their work is charged to the run's meter
//! (`crate::meter`); a solver sees only its `crate::allowance::Allowance`.

pub mod kept_proofs;
pub mod kept_solves;

pub use kept_proofs::KeptProofs;
pub use kept_solves::fingerprint_of;
pub use kept_solves::{Asked, Changed, Earlier, KeptSolves, SolveMap, SolvesFor};
