//! Test helpers: writing and reading images through the exr crate's
//! whole-image API (independent of exrcomp's block reader and writer), a
//! naive whole-image reference merge, running the binary, and the peers.
#![allow(dead_code)]

use exr::image::{AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer};
use exr::prelude::{Blocks, Compression, LayerAttributes, LineOrder, Text, WritableImage};
use half::f16;
use std::collections::{BTreeMap, BTreeSet};
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

pub fn exrcomp() -> Command {
    Command::new(env!("CARGO_BIN_EXE_exrcomp"))
}

/// exrcomp started with `args`, its output thrown away: a run to signal.
pub fn started(args: &[&str]) -> std::process::Child {
    let quiet = std::process::Stdio::null;
    let child = exrcomp().args(args).stdout(quiet()).stderr(quiet()).spawn();
    child.expect("exrcomp starts")
}

/// Sends `signal` (`-INT`, `-TERM`, `-KILL`) to `child`.
pub fn signal(child: &std::process::Child, signal: &str) {
    let kill = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status();
    assert!(kill.unwrap().success(), "kill {signal}");
}

/// Runs exrcomp with `args`; returns its output.
pub fn run(args: &[&str]) -> Output {
    exrcomp().args(args).output().expect("exrcomp runs")
}

/// `exrcomp generate PATH --kind KIND --width W --height H ARGS... -q`.
pub fn generate(path: &Path, kind: &str, (width, height): (usize, usize), args: &[&str]) {
    let (w, h) = (width.to_string(), height.to_string());
    let mut command = vec![
        "generate",
        path.to_str().unwrap(),
        "--kind",
        kind,
        "--width",
        &w,
        "--height",
        &h,
        "-q",
    ];
    command.extend_from_slice(args);
    let out = run(&command);
    assert!(out.status.success(), "{}", stderr(&out));
}

/// Runs exrcomp under a 4 GiB address-space limit (an allocation sized from
/// a damaged header would abort the process instead of passing quietly).
pub fn limited(args: &[&str]) -> Output {
    limited_command(args).output().expect("sh runs")
}

fn limited_command(args: &[&str]) -> Command {
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg("ulimit -v 4194304; exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_exrcomp"))
        .args(args);
    command
}

/// How a `within` run ended.
pub struct Ended {
    /// The exit code; `None` when a signal ended it or it was killed.
    pub code: Option<i32>,
    /// The signal that ended it (SIGABRT for a failed allocation).
    pub signal: Option<i32>,
    /// Killed for running past its time.
    pub timed_out: bool,
    pub stdout: String,
    pub stderr: String,
}

/// `limited`, killed after `timeout`.
pub fn limited_within(args: &[&str], timeout: Duration) -> Ended {
    within(limited_command(args), timeout)
}

/// Runs `command`, killed after `timeout`. Its output goes to files, so
/// that a long message (a backtrace) cannot block it on a full pipe.
pub fn within(mut command: Command, timeout: Duration) -> Ended {
    let log = || tempfile::tempfile().expect("temporary file");
    let (mut out, mut err) = (log(), log());
    let mut child = command
        .stdout(out.try_clone().expect("file handle"))
        .stderr(err.try_clone().expect("file handle"))
        .spawn()
        .expect("the command starts");
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("child waited for") {
            break Some(status);
        }
        if started.elapsed() > timeout {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let read = |log: &mut std::fs::File| {
        let mut text = String::new();
        log.rewind().expect("rewind");
        let _ = log.read_to_string(&mut text);
        text
    };
    Ended {
        code: status.and_then(|s| s.code()),
        signal: status.and_then(|s| std::os::unix::process::ExitStatusExt::signal(&s)),
        timed_out: status.is_none(),
        stdout: read(&mut out),
        stderr: read(&mut err),
    }
}

pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

pub fn s(path: &Path) -> &str {
    path.to_str().expect("test paths are UTF-8")
}

/// Frames `NAME.####.exr` of random 48x40 half RGBA, zip, in `dir`.
pub fn write_sequence(dir: &Path, name: &str, frames: impl IntoIterator<Item = i64>, seed: u64) {
    for frame in frames {
        let img = random_rgba(seed + frame as u64, 0, 0, 48, 40, Kind::Half, false);
        let path = dir.join(format!("{name}.{frame:04}.exr"));
        write_image(&path, &img, compression("zip"), LineOrder::Increasing);
    }
}

/// The few small images of OpenEXR's public test set shipped with the
/// repository, in the shared set's layout (tests/images/README.md).
pub fn shipped_images() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/images")
}

/// Where the whole shared set is looked for: `$EXRCOMP_SHARED_IMAGES`, else
/// `../shared/exr-images` beside the repository.
fn shared_root() -> PathBuf {
    std::env::var_os("EXRCOMP_SHARED_IMAGES")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/exr-images"))
}

/// The whole shared set of OpenEXR's public test images, or `None` (a
/// skipped check, see `missing`) when it is absent.
pub fn shared_images() -> Option<PathBuf> {
    shared_set("")
}

/// The second shared set (`../shared/exr-images-more`, or
/// `$EXRCOMP_SHARED_IMAGES_MORE`: more of OpenEXR's public images, such as
/// LuminanceChroma), or `None`, a skipped check: CI need not have it.
pub fn shared_more_images() -> Option<PathBuf> {
    let root = std::env::var_os("EXRCOMP_SHARED_IMAGES_MORE")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/exr-images-more"));
    if root.is_dir() {
        return Some(root);
    }
    skip(&format!(
        "the second shared image set {} is absent (set EXRCOMP_SHARED_IMAGES_MORE)",
        root.display()
    ));
    None
}

/// OpenColorIO's own test files (`../shared/ocio-test-files`, or
/// `$EXRCOMP_OCIO_TEST_FILES`), or `None`, a skipped check: CI need not
/// have them.
pub fn ocio_test_files() -> Option<PathBuf> {
    let root = std::env::var_os("EXRCOMP_OCIO_TEST_FILES")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/ocio-test-files"));
    if root.is_dir() {
        return Some(root);
    }
    skip(&format!(
        "OpenColorIO's test files {} are absent (set EXRCOMP_OCIO_TEST_FILES)",
        root.display()
    ));
    None
}

/// One image by its path in the shared set (`DisplayWindow/t08.exr`): the
/// shipped copy, else the shared set's, else `None` (a skipped check).
pub fn public_image(name: &str) -> Option<PathBuf> {
    let shipped = shipped_images().join(name);
    if shipped.is_file() {
        return Some(shipped);
    }
    shared_set(&format!("{name} is not in tests/images and ")).map(|root| root.join(name))
}

/// The shared set, or `None` with `why` leading the reason it is missing.
fn shared_set(why: &str) -> Option<PathBuf> {
    let root = shared_root();
    if root.is_dir() {
        return Some(root);
    }
    missing(&format!(
        "{why}the shared image set {} is absent (set EXRCOMP_SHARED_IMAGES)",
        root.display()
    ));
    None
}

/// Something a check needs is missing (a peer tool, the shared images): a
/// failure under EXRCOMP_REQUIRE_PEERS=1 (CI), else a skipped check.
pub fn missing(what: &str) {
    if std::env::var("EXRCOMP_REQUIRE_PEERS").as_deref() == Ok("1") {
        panic!("{what}, but EXRCOMP_REQUIRE_PEERS=1 requires it");
    }
    skip(what);
}

/// The checks skipped in this test binary, as "test: reason".
static SKIPPED: Mutex<BTreeSet<String>> = Mutex::new(BTreeSet::new());

/// Records a skipped check of the running test. The test binary lists its
/// skipped checks, counted, after its `test result:` line: printed at exit,
/// on the process's stderr itself, which the test harness does not capture
/// (it captures only `print!`/`eprint!` of a test's thread).
pub fn skip(reason: &str) {
    static AT_EXIT: Once = Once::new();
    // SAFETY: `report_skipped` is an `extern "C" fn()` that never unwinds.
    AT_EXIT.call_once(|| assert_eq!(unsafe { libc::atexit(report_skipped) }, 0));
    let test = std::thread::current().name().unwrap_or("?").to_string();
    SKIPPED
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(format!("{test}: {reason}"));
}

extern "C" fn report_skipped() {
    let skipped = SKIPPED.lock().unwrap_or_else(|e| e.into_inner());
    let mut text = format!("SKIPPED: {} check(s) in this test binary:\n", skipped.len());
    for line in skipped.iter() {
        text += &format!("    {line}\n");
    }
    let _ = std::io::stderr().write_all(text.as_bytes());
}

/// A channel's samples, in its own type.
#[derive(Clone, Debug, PartialEq)]
pub enum Samples {
    F16(Vec<f16>),
    F32(Vec<f32>),
    U32(Vec<u32>),
}

impl Samples {
    pub fn get_f32(&self, i: usize) -> f32 {
        match self {
            Samples::F16(v) => v[i].to_f32(),
            Samples::F32(v) => v[i],
            Samples::U32(v) => v[i] as f32,
        }
    }

    pub fn bits(&self, i: usize) -> u32 {
        match self {
            Samples::F16(v) => v[i].to_bits() as u32,
            Samples::F32(v) => v[i].to_bits(),
            Samples::U32(v) => v[i],
        }
    }

    pub fn len(&self) -> usize {
        match self {
            Samples::F16(v) => v.len(),
            Samples::F32(v) => v.len(),
            Samples::U32(v) => v.len(),
        }
    }

    pub fn zeros_like(&self, len: usize) -> Samples {
        match self {
            Samples::F16(_) => Samples::F16(vec![f16::ZERO; len]),
            Samples::F32(_) => Samples::F32(vec![0.0; len]),
            Samples::U32(_) => Samples::U32(vec![0; len]),
        }
    }

    pub fn set_f32(&mut self, i: usize, value: f32) {
        match self {
            Samples::F16(v) => v[i] = f16::from_f32(value),
            Samples::F32(v) => v[i] = value,
            Samples::U32(v) => v[i] = value as u32,
        }
    }

    pub fn copy_from(&mut self, i: usize, other: &Samples, j: usize) {
        match (self, other) {
            (Samples::F16(a), Samples::F16(b)) => a[i] = b[j],
            (Samples::F32(a), Samples::F32(b)) => a[i] = b[j],
            (Samples::U32(a), Samples::U32(b)) => a[i] = b[j],
            _ => panic!("type mismatch"),
        }
    }
}

/// A flat single-part image: data window, display window, named channels.
#[derive(Clone, Debug)]
pub struct Img {
    pub x: i32,
    pub y: i32,
    pub width: usize,
    pub height: usize,
    pub display: (usize, usize),
    pub channels: BTreeMap<String, Samples>,
}

impl Img {
    /// Index of absolute pixel (x, y) if it is inside the data window.
    pub fn index(&self, x: i32, y: i32) -> Option<usize> {
        let (dx, dy) = (x - self.x, y - self.y);
        (dx >= 0 && dy >= 0 && (dx as usize) < self.width && (dy as usize) < self.height)
            .then(|| dy as usize * self.width + dx as usize)
    }
}

/// Deterministic pseudo-random numbers in [0, 1).
pub struct Lcg(pub u64);

impl Lcg {
    pub fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

pub enum Kind {
    Half,
    Float,
}

/// A premultiplied RGBA image with random alpha (including exact 0 and 1),
/// colours up to 1.5x alpha, plus `extra` pass-through channels
/// (a float Z and a u32 id).
pub fn random_rgba(
    seed: u64,
    x: i32,
    y: i32,
    width: usize,
    height: usize,
    kind: Kind,
    extra: bool,
) -> Img {
    let mut rng = Lcg(seed);
    let n = width * height;
    let alpha: Vec<f32> = (0..n)
        .map(|_| match rng.next() {
            r if r < 0.2 => 0.0,
            r if r < 0.4 => 1.0,
            _ => rng.next(),
        })
        .collect();
    let mut channels = BTreeMap::new();
    let make = |values: Vec<f32>| match kind {
        Kind::Half => Samples::F16(values.into_iter().map(f16::from_f32).collect()),
        Kind::Float => Samples::F32(values),
    };
    for name in ["R", "G", "B"] {
        let values = alpha.iter().map(|&a| a * rng.next() * 1.5).collect();
        channels.insert(name.to_string(), make(values));
    }
    channels.insert("A".to_string(), make(alpha));
    if extra {
        channels.insert(
            "Z".into(),
            Samples::F32((0..n).map(|_| rng.next() * 100.0).collect()),
        );
        channels.insert(
            "id".into(),
            Samples::U32((0..n).map(|_| (rng.next() * 4e9) as u32).collect()),
        );
    }
    Img {
        x,
        y,
        width,
        height,
        display: (64, 48),
        channels,
    }
}

/// `img` as one layer (part) of an image, with `attributes` for its header.
fn layer(
    img: &Img,
    attributes: LayerAttributes,
    encoding: Encoding,
) -> Layer<AnyChannels<FlatSamples>> {
    let channels: Vec<AnyChannel<FlatSamples>> = img
        .channels
        .iter()
        .map(|(name, s)| {
            let samples = match s {
                Samples::F16(v) => FlatSamples::F16(v.clone()),
                Samples::F32(v) => FlatSamples::F32(v.clone()),
                Samples::U32(v) => FlatSamples::U32(v.clone()),
            };
            AnyChannel::new(name.as_str(), samples)
        })
        .collect();
    let attributes = LayerAttributes {
        layer_position: exr::math::Vec2(img.x, img.y),
        comments: Some("written by the tests".into()),
        ..attributes
    };
    Layer::new(
        (img.width, img.height),
        attributes,
        encoding,
        AnyChannels::sort(channels.into()),
    )
}

pub fn write_image(path: &Path, img: &Img, compression: Compression, line_order: LineOrder) {
    let encoding = Encoding {
        compression,
        blocks: Blocks::ScanLines,
        line_order,
    };
    write_encoded(path, img, encoding);
}

/// A W x H image of `channels` at the origin, written as a ZIP file.
pub fn write_flat(
    path: &Path,
    (width, height): (usize, usize),
    channels: std::collections::BTreeMap<String, Samples>,
) {
    let img = Img {
        x: 0,
        y: 0,
        width,
        height,
        display: (width, height),
        channels,
    };
    write_image(path, &img, Compression::ZIP16, LineOrder::Increasing);
}

/// A single-part file stored as `encoding` says (scanlines or tiles).
pub fn write_encoded(path: &Path, img: &Img, encoding: Encoding) {
    let layer = layer(img, LayerAttributes::default(), encoding);
    let mut image = Image::from_layer(layer);
    image.attributes.display_window =
        exr::meta::attribute::IntegerBounds::from_dimensions(img.display);
    image.write().to_file(path).expect("test image written");
}

pub fn zip_scanlines() -> Encoding {
    Encoding {
        compression: Compression::ZIP16,
        blocks: Blocks::ScanLines,
        line_order: LineOrder::Increasing,
    }
}

/// A single-part multi-view file: `img`'s channels under a `multiView`
/// attribute listing `views`, the first of them the default view (ZIP).
pub fn write_multi_view(path: &Path, img: &Img, views: &[&str]) {
    let attributes = LayerAttributes {
        multi_view_names: Some(views.iter().map(|&v| v.into()).collect()),
        ..Default::default()
    };
    let layer = layer(img, attributes, zip_scanlines());
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .expect("test image written");
}

/// A multi-part file: per part its name, its view and its pixels (ZIP).
pub fn write_parts(path: &Path, parts: &[(&str, &str, &Img)]) {
    let zip = zip_scanlines();
    let parts: Vec<_> = parts.iter().map(|&(n, v, img)| (n, v, img, zip)).collect();
    write_encoded_parts(path, &parts);
}

/// A multi-part file: per part its name, its view, its pixels and how they
/// are stored (compression, scanlines or tiles).
pub fn write_encoded_parts(path: &Path, parts: &[(&str, &str, &Img, Encoding)]) {
    write_parts_listing(path, parts, false);
}

/// As `write_encoded_parts`, with `listing` every part also listing all the
/// parts' views in a `multiView` attribute (as some stereo writers do).
pub fn write_parts_listing(path: &Path, parts: &[(&str, &str, &Img, Encoding)], listing: bool) {
    let views: Vec<Text> = parts.iter().map(|&(_, view, _, _)| view.into()).collect();
    let layers: Vec<_> = parts
        .iter()
        .map(|&(name, view, img, encoding)| {
            let attributes = LayerAttributes {
                layer_name: Some(name.into()),
                view_name: Some(view.into()),
                multi_view_names: listing.then(|| views.clone()),
                ..Default::default()
            };
            layer(img, attributes, encoding)
        })
        .collect();
    let display = exr::meta::attribute::IntegerBounds::from_dimensions(parts[0].2.display);
    let image = Image::from_layers(exr::meta::header::ImageAttributes::new(display), layers);
    image.write().to_file(path).expect("test image written");
}

pub fn read_image(path: &Path) -> Img {
    read_parts(path).swap_remove(0)
}

/// Every part of `path`, in file order.
pub fn read_parts(path: &Path) -> Vec<Img> {
    let image =
        exr::prelude::read_all_flat_layers_from_file(path).expect("readable by the exr crate");
    let display = image.attributes.display_window.size;
    image
        .layer_data
        .iter()
        .map(|layer| {
            let channels = layer
                .channel_data
                .list
                .iter()
                .map(|c| {
                    let samples = match &c.sample_data {
                        FlatSamples::F16(v) => Samples::F16(v.clone()),
                        FlatSamples::F32(v) => Samples::F32(v.clone()),
                        FlatSamples::U32(v) => Samples::U32(v.clone()),
                    };
                    (c.name.to_string(), samples)
                })
                .collect();
            Img {
                x: layer.attributes.layer_position.x(),
                y: layer.attributes.layer_position.y(),
                width: layer.size.width(),
                height: layer.size.height(),
                display: (display.width(), display.height()),
                channels,
            }
        })
        .collect()
}

/// Alpha at a pixel for a layer with channel prefix `prefix`: its own A,
/// else the unnamed A, else 1 inside the data window; 0 outside it.
fn alpha_at(img: &Img, prefix: &str, x: i32, y: i32) -> f32 {
    match img.index(x, y) {
        None => 0.0,
        Some(i) => img
            .channels
            .get(&format!("{prefix}A"))
            .or(img.channels.get("A"))
            .map_or(1.0, |a| a.get_f32(i)),
    }
}

fn value_at(img: &Img, name: &str, x: i32, y: i32) -> f32 {
    match (img.index(x, y), img.channels.get(name)) {
        (Some(i), Some(s)) => s.get_f32(i),
        _ => 0.0,
    }
}

/// specs/ops.md's merge formulas, premultiplied, one sample. A term whose
/// alpha weight is exactly 0 is left out (so 0 · ∞ or 0 · NaN gives
/// nothing), one weighed 1 is the sample itself.
pub fn merge_formula(op: &str, a: f32, aa: f32, b: f32, ab: f32) -> f32 {
    let times = |w: f32, x: f32| {
        if w == 0.0 {
            0.0
        } else if w == 1.0 {
            x
        } else {
            w * x
        }
    };
    let plus = |x: f32, w: f32, y: f32| if w == 0.0 { x } else { x + w * y };
    match op {
        "over" => plus(a, 1.0 - aa, b),
        "under" => plus(b, 1.0 - ab, a),
        "in" => times(ab, a),
        "out" => times(1.0 - ab, a),
        "atop" => plus(times(ab, a), 1.0 - aa, b),
        "xor" => plus(times(1.0 - ab, a), 1.0 - aa, b),
        "plus" => a + b,
        "minus" => a - b,
        "from" => b - a,
        "multiply" => a * b,
        "screen" if a > 1.0 && b > 1.0 => a.max(b),
        "screen" => a + b - a * b,
        "max" => a.max(b),
        "min" => a.min(b),
        "difference" => (a - b).abs(),
        "divide" if b == 0.0 => 0.0,
        "divide" => a / b,
        "mask" => times(aa, b),
        "stencil" => times(1.0 - aa, b),
        "copy" => a,
        _ => panic!("unknown operator {op}"),
    }
}

pub const MERGE_OPS: [&str; 18] = [
    "over",
    "under",
    "in",
    "out",
    "atop",
    "xor",
    "plus",
    "minus",
    "from",
    "multiply",
    "screen",
    "max",
    "min",
    "difference",
    "divide",
    "mask",
    "stencil",
    "copy",
];

/// The whole-image reference merge of A over B (specs/ops.md): the result
/// window by the operator's rule, then pixel by pixel in f32 for the layers
/// with channel prefixes `layers` ("" is the unnamed one); other channels
/// copied from B.
pub fn reference_merge(
    op: &str,
    a: &Img,
    b: &Img,
    straight: bool,
    mix: f32,
    layers: &[&str],
) -> Img {
    let window = |img: &Img| {
        (
            img.x,
            img.y,
            img.x + img.width as i32,
            img.y + img.height as i32,
        )
    };
    let (wa, wb) = (window(a), window(b));
    let union = (
        wa.0.min(wb.0),
        wa.1.min(wb.1),
        wa.2.max(wb.2),
        wa.3.max(wb.3),
    );
    let meet = (
        wa.0.max(wb.0),
        wa.1.max(wb.1),
        wa.2.min(wb.2),
        wa.3.min(wb.3),
    );
    let mut w = match op {
        "in" | "mask" | "multiply" | "divide" => meet,
        "out" | "copy" => wa,
        "atop" | "stencil" => wb,
        _ => union,
    };
    if mix < 1.0 {
        w = (w.0.min(wb.0), w.1.min(wb.1), w.2.max(wb.2), w.3.max(wb.3));
    }
    let (x0, y0, x1, y1) = w;
    let (width, height) = ((x1 - x0) as usize, (y1 - y0) as usize);
    // Where a transparent black A leaves B exactly as it is.
    let keeps_b =
        !straight && ["over", "under", "atop", "xor", "plus", "from", "stencil"].contains(&op);
    let mut channels: BTreeMap<String, Samples> = BTreeMap::new();
    for (name, s) in &b.channels {
        channels.insert(name.clone(), s.zeros_like(width * height));
    }
    for prefix in layers {
        for base in ["R", "G", "B", "A"] {
            let name = format!("{prefix}{base}");
            if let (Some(s), false) = (a.channels.get(&name), b.channels.contains_key(&name)) {
                channels.insert(name, s.zeros_like(width * height));
            }
        }
    }
    let blend = |r: f32, b: f32| if mix == 1.0 { r } else { b + mix * (r - b) };
    for (name, out) in channels.iter_mut() {
        let (layer, base) = match name.rsplit_once('.') {
            Some((l, base)) => (format!("{l}."), base),
            None => (String::new(), name.as_str()),
        };
        let composited = layers.contains(&layer.as_str()) && ["R", "G", "B", "A"].contains(&base);
        for y in y0..y1 {
            for x in x0..x1 {
                let i = (y - y0) as usize * width + (x - x0) as usize;
                if !composited {
                    if let Some(j) = b.index(x, y) {
                        out.copy_from(i, &b.channels[name], j);
                    }
                    continue;
                }
                let aa = alpha_at(a, &layer, x, y);
                let ab = alpha_at(b, &layer, x, y);
                let ar = if keeps_b && aa == 0.0 {
                    ab
                } else if op == "atop" {
                    blend(ab, ab)
                } else {
                    blend(merge_formula(op, aa, aa, ab, ab), ab)
                };
                if base == "A" {
                    out.set_f32(i, ar);
                    continue;
                }
                let (ca, cb) = (value_at(a, name, x, y), value_at(b, name, x, y));
                let c = if keeps_b && aa == 0.0 && ca == 0.0 {
                    cb
                } else if straight {
                    let p = blend(merge_formula(op, ca * aa, aa, cb * ab, ab), cb * ab);
                    if ar == 0.0 {
                        0.0
                    } else {
                        p / ar
                    }
                } else {
                    blend(merge_formula(op, ca, aa, cb, ab), cb)
                };
                out.set_f32(i, c);
            }
        }
    }
    Img {
        x: x0,
        y: y0,
        width,
        height,
        display: b.display,
        channels,
    }
}

/// `over` of the unnamed layer, as `exrcomp over` does it.
pub fn reference_over(fg: &Img, bg: &Img, straight: bool) -> Img {
    reference_merge("over", fg, bg, straight, 1.0, &[""])
}

/// Panics with the first differing sample unless `a` and `b` are identical
/// to the bit (windows, channel names and types, samples).
pub fn assert_identical(a: &Img, b: &Img) {
    assert_eq!(
        (a.x, a.y, a.width, a.height),
        (b.x, b.y, b.width, b.height),
        "data windows differ"
    );
    assert_eq!(a.display, b.display, "display windows differ");
    let names_a: Vec<_> = a.channels.keys().collect();
    let names_b: Vec<_> = b.channels.keys().collect();
    assert_eq!(names_a, names_b, "channel lists differ");
    for (name, sa) in &a.channels {
        let sb = &b.channels[name];
        assert_eq!(
            std::mem::discriminant(sa),
            std::mem::discriminant(sb),
            "channel {name} type differs"
        );
        for i in 0..sa.len() {
            assert_eq!(
                sa.bits(i),
                sb.bits(i),
                "channel {name} differs at pixel ({}, {}): {} vs {}",
                a.x + (i % a.width) as i32,
                a.y + (i / a.width) as i32,
                sa.get_f32(i),
                sb.get_f32(i)
            );
        }
    }
}

/// Runs `command` (a peer making a test file); panics with its stderr if it fails.
/// Decodes an 8-bit RGB PNG with Python's zlib and struct (no filter
/// assumed: each row's filter type is undone as PNG defines them):
/// width, height and the pixels.
pub fn decode_png(path: &Path) -> Option<(usize, usize, Vec<[u8; 3]>)> {
    let python = peer("python3")?;
    let script = r#"
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n'
at, idat = 8, b''
while at < len(data):
    n, kind = struct.unpack('>I4s', data[at:at + 8])
    body = data[at + 8:at + 8 + n]
    assert struct.unpack('>I', data[at + 8 + n:at + 12 + n])[0] == zlib.crc32(kind + body), kind
    if kind == b'IHDR':
        w, h, depth, colour = struct.unpack('>IIBB', body[:10])
        assert (depth, colour) == (8, 2)
    elif kind == b'IDAT':
        idat += body
    at += 12 + n
raw, stride, rows, prev = zlib.decompress(idat), 3 * w, [], bytearray(3 * w)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - 3] if i >= 3 else 0
        b, c = prev[i], (prev[i - 3] if i >= 3 else 0)
        p = a + b - c
        pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
        pred = [0, a, b, (a + b) // 2, a if pa <= pb and pa <= pc else (b if pb <= pc else c)][f]
        line[i] = (line[i] + pred) & 255
    rows.append(bytes(line))
    prev = line
sys.stdout.buffer.write(struct.pack('>II', w, h) + b''.join(rows))
"#;
    let out = Command::new(python)
        .args(["-c", script])
        .arg(path)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", stderr(&out));
    let w = u32::from_be_bytes(out.stdout[0..4].try_into().unwrap()) as usize;
    let h = u32::from_be_bytes(out.stdout[4..8].try_into().unwrap()) as usize;
    let pixels = out.stdout[8..]
        .chunks(3)
        .map(|p| [p[0], p[1], p[2]])
        .collect::<Vec<_>>();
    assert_eq!(pixels.len(), w * h);
    Some((w, h, pixels))
}

/// Runs a job file in `dir` reading `input` through one op node (its keys
/// `keys`, as TOML lines) and returns the file it wrote.
pub fn one_op_job(dir: &Path, input: &Path, keys: &str) -> PathBuf {
    let job = dir.join("job.toml");
    let output = dir.join("job.exr");
    std::fs::write(
        &job,
        format!(
            "[[node]]\nname = \"in\"\nread = \"{}\"\n\n[[node]]\nname = \"op\"\n{keys}\ninputs = [\"in\"]\n\n[[node]]\nname = \"out\"\nwrite = \"{}\"\ninputs = [\"op\"]\n",
            s(input),
            s(&output)
        ),
    )
    .unwrap();
    let ran = run(&["run", s(&job), "--quiet"]);
    assert!(ran.status.success(), "{}", stderr(&ran));
    output
}

/// `exrcomp OP INPUT -o OUTPUT ARGS...` fails for each case, saying what
/// it says, and writes nothing.
pub fn assert_refused(op: &str, input: &Path, output: &Path, cases: &[(&[&str], &str)]) {
    for &(args, says) in cases {
        let mut all = vec![op, s(input), "-o", s(output)];
        all.extend(args);
        let result = run(&all);
        assert!(!result.status.success(), "{args:?} accepted");
        assert!(
            stderr(&result).contains(says),
            "{args:?}: {}",
            stderr(&result)
        );
        assert!(!output.exists(), "{args:?} wrote a file");
    }
}

/// Runs exrcomp with `args`, which must succeed.
/// The memory bound a `--dry-run` said ("holding at most N MiB"), in bytes.
pub fn memory_bound(dry_run: &Output) -> u64 {
    let said = stderr(dry_run);
    let mib: u64 = said
        .split("holding at most ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|mib| mib.parse().ok())
        .unwrap_or_else(|| panic!("no bound in {said}"));
    mib << 20
}

pub fn ok(args: &[&str]) {
    let out = run(args);
    assert!(out.status.success(), "exrcomp {args:?}: {}", stderr(&out));
}

pub fn succeed(command: &mut Command) -> Output {
    let out = command.output().expect("the command starts");
    assert!(
        out.status.success(),
        "{command:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// A peer tool, or `None` (a skipped check, see `missing`) when it is not
/// installed.
pub fn peer(name: &str) -> Option<PathBuf> {
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|p| p.join(name))
            .find(|p| p.is_file())
    });
    if found.is_none() {
        missing(&format!("peer tool {name} is not installed"));
    }
    found
}

/// Decodes every pixel of `path` through OpenEXR's C++ library (oiiotool
/// --printstats) and parses its header with exrheader; panics on failure.
pub fn assert_peers_read(path: &Path) {
    if let Some(oiiotool) = peer("oiiotool") {
        let out = Command::new(oiiotool)
            .arg(path)
            .arg("--printstats")
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).to_string()
            + &String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.success() && !text.to_lowercase().contains("error"),
            "oiiotool cannot decode {}: {text}",
            path.display()
        );
    }
    if let Some(exrheader) = peer("exrheader") {
        let out = Command::new(exrheader).arg(path).output().unwrap();
        assert!(
            out.status.success(),
            "exrheader cannot read {}: {}",
            path.display(),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

pub fn compression(name: &str) -> Compression {
    match name {
        "none" => Compression::Uncompressed,
        "rle" => Compression::RLE,
        "zips" => Compression::ZIP1,
        "zip" => Compression::ZIP16,
        "piz" => Compression::PIZ,
        "pxr24" => Compression::PXR24,
        "b44" => Compression::B44,
        "b44a" => Compression::B44A,
        other => panic!("no compression {other} in the tests"),
    }
}

/// `idiff -fail 0`: every pixel of every channel identical.
pub fn assert_idiff_identical(idiff: &Path, a: &Path, b: &Path) {
    let out = Command::new(idiff)
        .args(["-fail", "0", "-warn", "0"])
        .arg(a)
        .arg(b)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "idiff finds {} and {} differ:\n{}",
        a.display(),
        b.display(),
        String::from_utf8_lossy(&out.stdout)
    );
}

/// Far above any hostile run's time (well under a second each in a debug build).
const HOSTILE_TIMEOUT: Duration = Duration::from_secs(60);

/// Arguments from a damaged file, a good plate and an output path.
pub type HostileArgs = fn(&str, &str, &str) -> Vec<String>;

/// The commands a damaged file goes through (tests/suite/damaged_corpus.rs,
/// tests/suite/hostile.rs), by name: their arguments for the damaged file, a good
/// plate and the output path.
pub fn hostile_commands() -> Vec<(&'static str, HostileArgs)> {
    fn v(args: &[&str]) -> Vec<String> {
        args.iter().map(|a| a.to_string()).collect()
    }
    vec![
        ("over (damaged fg)", |d, good, out| {
            v(&["over", d, good, "-o", out, "-q", "--threads", "8"])
        }),
        ("over (damaged bg)", |d, good, out| {
            v(&["over", good, d, "-o", out, "-q", "--threads", "8"])
        }),
        ("transcode", |d, _, out| {
            v(&["transcode", d, "-o", out, "-q", "--threads", "8"])
        }),
        ("blur", |d, _, out| {
            v(&["blur", "--radius", "3", d, "-o", out, "-q"])
        }),
        ("flatten", |d, _, out| v(&["flatten", d, "-o", out, "-q"])),
        ("info", |d, _, _| v(&["info", d])),
    ]
}

/// Whether OpenEXR (oiiotool) decodes every pixel of `path`; without
/// oiiotool, exrcomp's own check.
fn decodes(path: &Path, oiiotool: Option<&Path>) -> Result<(), String> {
    let out = match oiiotool {
        Some(tool) => Command::new(tool).arg("--stats").arg(path).output(),
        None => exrcomp().arg("info").arg(path).output(),
    }
    .expect("the checker runs");
    let text = String::from_utf8_lossy(&out.stdout).to_string() + &stderr(&out);
    if out.status.success() && !text.to_lowercase().contains("error") {
        Ok(())
    } else {
        Err(text)
    }
}

/// Runs `args` (one of `hostile_commands`) on `damaged`, writing `out` in
/// the empty folder `work`: its exit code and what is wrong, if anything
/// (anything but a decodable output or a one-line error naming the file,
/// with nothing else left in `work`).
pub fn hostile_run(
    damaged: &Path,
    args: &[String],
    work: &Path,
    out: &Path,
    oiiotool: Option<&Path>,
) -> (Option<i32>, Option<String>) {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let ended = limited_within(&args, HOSTILE_TIMEOUT);
    let name = damaged.file_name().unwrap().to_str().unwrap();
    let message = ended.stderr.trim_end();
    let mut left: Vec<String> = std::fs::read_dir(work)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    let wrong = match ended.code {
        _ if ended.timed_out => Some(format!("still running after {HOSTILE_TIMEOUT:?}")),
        Some(0) if left != ["out.exr"] && args[0] != "info" => {
            Some(format!("exit 0, output folder holds {left:?}"))
        }
        Some(0) => match args[0] {
            "info" => None,
            _ => decodes(out, oiiotool)
                .err()
                .map(|e| format!("exit 0 but the output does not decode: {e}")),
        },
        Some(3) if !left.is_empty() => Some(format!("exit 3, left {left:?}")),
        Some(3) if message.lines().count() != 1 || !message.contains(name) => Some(format!(
            "exit 3 without a one-line message naming the file: {message}"
        )),
        Some(3) => None,
        code => Some(format!(
            "exit {code:?} (signal {:?}), left {left:?}: {}",
            ended.signal,
            message.lines().next().unwrap_or("")
        )),
    };
    (ended.code, wrong)
}

/// Appends raw header attributes (name, type name, value bytes), as an EXR
/// header lays them out, and the null byte that ends the header.
pub fn put_attributes(file: &mut Vec<u8>, attributes: &[(&str, &str, Vec<u8>)]) {
    for (name, kind, value) in attributes {
        for text in [name, kind] {
            file.extend(text.as_bytes());
            file.push(0);
        }
        file.extend((value.len() as i32).to_le_bytes());
        file.extend(value);
    }
    file.push(0);
}

/// The bytes of every chunk of `part` of `path` as stored (part number,
/// coordinates, sizes and data), in offset-table order: a part carried into
/// another file has the same.
pub fn part_chunks(path: &Path, part: usize) -> Vec<Vec<u8>> {
    let file = exrcomp::io::reader::ExrFile::open(path, None).unwrap();
    let bytes = std::fs::read(path).unwrap();
    (0..file.header(part).chunk_count)
        .map(|k| {
            let range = file.chunk_range(part, k);
            bytes[range.start as usize..range.end as usize].to_vec()
        })
        .collect()
}

/// A python with PyPI's OpenEXR (`$EXRCOMP_OPENEXR_PYTHON`, else `python3`),
/// or `None` (a skipped check).
pub fn openexr_python() -> Option<String> {
    let python = std::env::var("EXRCOMP_OPENEXR_PYTHON").unwrap_or_else(|_| "python3".into());
    let found = std::process::Command::new(&python)
        .args(["-c", "import OpenEXR, numpy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        missing(&format!("{python} cannot import PyPI's OpenEXR and numpy"));
    }
    found.then_some(python)
}

/// `bytes` of an exrcomp output with the value of every
/// `exrcomp:fingerprint` attribute (which job made the frame: two jobs
/// that write the same pixels record different ones) blanked, so that two
/// jobs' files compare byte for byte in everything else.
pub fn without_fingerprint(mut bytes: Vec<u8>) -> Vec<u8> {
    let name = b"exrcomp:fingerprint\0string\0";
    let mut at = 0;
    while let Some(i) = bytes[at..].windows(name.len()).position(|w| w == name) {
        let start = at + i + name.len() + 4;
        bytes[start..start + 32].fill(b'-');
        at = start + 32;
    }
    bytes
}

/// Whether the files at `a` and `b` are the same bytes but for their
/// fingerprints (`without_fingerprint`).
pub fn same_but_fingerprint(a: &Path, b: &Path) -> bool {
    let read = |p: &Path| without_fingerprint(std::fs::read(p).unwrap());
    read(a) == read(b)
}
