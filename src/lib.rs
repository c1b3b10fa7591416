//! exrcomp: a streaming OpenEXR sequence compositor.

pub mod bench;
pub mod bench_chart;
pub mod cli;
pub mod commands;
pub mod engine;
pub mod error;
pub mod farm;
pub mod generate;
pub mod guard;
pub mod info;
pub mod io;
pub mod job;
pub mod ops;
pub mod params;
pub mod report;
