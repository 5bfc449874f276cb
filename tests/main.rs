//! The integration tests, one binary: each module is the file of its name
//! under tests/ (ARCHITECTURE.md says what each checks).

mod bases;
mod beyond;
mod body;
mod body_check;
mod browser;
mod cache;
mod calibration;
mod checker;
mod cli;
mod docs_picture;
mod docs_tables;
mod ecosystem;
mod facing;
mod gaze;
mod golden;
mod hands;
mod hostile;
mod independent;
mod invariance;
mod layers;
mod limits;
mod meshes;
mod parser;
mod placement;
mod plugins;
mod population;
mod properties;
mod retry;
mod routes;
mod standards;
mod stdlib;
mod suite;
mod urdf;
mod watch;
mod why;
