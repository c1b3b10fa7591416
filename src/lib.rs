//! exrcomp: a streaming OpenEXR sequence compositor.

pub mod bench;
pub mod bench_chart;
pub mod cli;
pub mod commands;
pub mod contact_sheet;
pub mod demo;
pub mod engine;
pub mod error;
pub mod farm;
pub mod font;
pub mod generate;
pub mod guard;
pub mod info;
pub mod io;
pub mod job;
pub mod ops;
pub mod params;
pub mod report;
pub mod slate;
pub mod stage_time;
