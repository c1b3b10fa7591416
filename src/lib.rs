//! exrcomp: a streaming OpenEXR sequence compositor.

pub mod cli;
pub mod draw;
pub mod engine;
pub mod error;
pub mod guard;
pub mod io;
pub mod ops;
pub mod params;
pub mod run;
pub mod simd;
pub mod stage_time;
pub mod tools;
