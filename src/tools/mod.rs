//! Tools built on runs: the benchmark and its chart, the demo and its contact
//! sheet, farm submission, and `info`.

pub mod bench;
pub mod bench_ab;
pub mod bench_chart;
pub mod bench_report;
pub mod bench_run;
pub mod bench_stats;
pub mod contact_sheet;
pub mod demo;
pub mod farm;
pub mod info;
