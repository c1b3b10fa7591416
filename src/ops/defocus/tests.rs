//! The layered sums against the exact gather of specs/ops.md, on random
//! depths and colours in memory.

use super::aperture::{need_table, Footprints};
use super::*;
use crate::io::text::Utf8Text;
use exr::meta::attribute::{IntegerBounds, SampleType};

/// The spec's gather, written directly: for each output pixel every sample
/// within R, tested one by one (what the op did before it was layered).
fn exact(op: &Defocus, input: &Rows, out: &mut Rows) {
    let names = op.layers.filtered(&input.channels);
    let (w, r) = (input.width, op.max_radius as i32);
    let side = 2 * r as usize + 1;
    let need = need_table(op.aperture, r);
    let held = input.valid_rows();
    let rows = (out.y - r).max(held.start)..(out.end() + r).min(held.end);
    let sources = input.valid_columns();
    let read = |name: &str, y: i32, x: usize| {
        let mut row = vec![0.0f32; w];
        let c = input.channel_index(name).unwrap();
        input.planes[c].read_f32(input.row_range(y), &mut row);
        row[x]
    };
    for y in out.valid_rows() {
        for c in 0..out.channels.len() {
            let name = out.channels[c].name.utf8();
            if !names.contains(&name) {
                let range = out.row_range(y);
                let s = input.channel_index(&name).unwrap();
                out.planes[c]
                    .bytes_mut(range)
                    .copy_from_slice(input.planes[s].bytes(input.row_range(y)));
            }
        }
        for name in &names {
            let c = out.channel_index(name).unwrap();
            let mut result = vec![0.0f32; w];
            for x in out.valid_columns() {
                let zp = read(&op.z_channel, y, x);
                let rp = op.coc(zp);
                let (mut sum, mut total) = (0.0f32, 0.0f32);
                for yq in (y - r).max(rows.start)..(y + r + 1).min(rows.end) {
                    let qx = x.saturating_sub(r as usize).max(sources.start)
                        ..(x + r as usize + 1).min(sources.end);
                    for xq in qx {
                        let d = need[(y - yq + r) as usize * side + x + r as usize - xq];
                        let zq = read(&op.z_channel, yq, xq);
                        let rq = op.coc(zq);
                        if d > rq || (zq > zp && d > rp) {
                            continue;
                        }
                        let weight = 1.0 / op.aperture.area(rq);
                        total += weight;
                        sum += weight * read(name, yq, xq);
                    }
                }
                result[x] = sum / total;
            }
            let range = out.row_range(y);
            let columns = out.valid_columns();
            out.planes[c].write_f32(
                range.start + columns.start..range.start + columns.end,
                &result[columns],
            );
        }
    }
}

struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Rows y0 .. y0 + height of a frame with random colours and depths around
/// `focus`, some of them special (the focus itself, 0, negative, NaN,
/// infinite), valid over `valid`.
fn frame(
    seed: u64,
    focus: f32,
    (y0, width, height): (i32, usize, usize),
    valid: IntegerBounds,
) -> Rows {
    let channels: Vec<ChannelDescription> = ["A", "B", "G", "R", "Z", "other"]
        .iter()
        .map(|&n| ChannelDescription::new(n, SampleType::F32, n != "Z"))
        .collect();
    let mut rows = Rows::zeros(-3, y0, width, height, channels, valid);
    let mut rng = Lcg(seed);
    for y in y0..y0 + height as i32 {
        let range = rows.row_range(y);
        for c in 0..rows.channels.len() {
            let values: Vec<f32> = (0..width)
                .map(
                    |_| match (rows.channels[c].name.utf8().as_str(), rng.next()) {
                        ("Z", u) if u < 0.04 => {
                            [focus, 0.0, -1.0, f32::NAN, f32::INFINITY][(u * 125.0) as usize]
                        }
                        ("Z", _) => focus * (0.3 + 2.5 * rng.next()),
                        (_, u) if u < 0.02 => 1000.0,
                        (_, u) => u * 2.0,
                    },
                )
                .collect();
            rows.planes[c].write_f32(range.clone(), &values);
        }
    }
    rows
}

/// Whether a and b agree to half precision: within 2^-11 of b.
fn close(a: f32, b: f32) -> bool {
    a == b || (a.is_nan() && b.is_nan()) || (a - b).abs() <= b.abs() / 2048.0
}

#[test]
fn layered_sums_equal_the_exact_gather_for_apertures_radii_and_strips() {
    let mut worst = 0.0f32;
    for (case, aperture) in [
        Aperture::Disc,
        Aperture::Polygon(6),
        Aperture::Polygon(5),
        Aperture::Polygon(3),
        Aperture::Polygon(8),
    ]
    .into_iter()
    .enumerate()
    {
        for (max_radius, scale, focus) in [
            (0, 3.0, 4.0),
            (1, 2.0, 4.0),
            (3, 9.0, 6.0),
            (6, 8.0, 5.0),
            (11, 30.0, 5.0),
            (5, 4.0, 0.0),
        ] {
            let op = Defocus {
                focus,
                scale,
                max_radius,
                aperture,
                z_channel: "Z".into(),
                layers: Selection::default(),
            };
            // An input strip with its halo (its top and right out of the
            // valid window), and output rows inside it.
            let (width, height) = (23 + 60 * case, 16 + 2 * max_radius);
            let valid = IntegerBounds::new((-3, -2), (width - 2, 100));
            let input = frame(
                case as u64 * 31 + max_radius as u64,
                focus.max(1.0),
                (-4, width, height),
                valid,
            );
            let out_rows = (-4 + max_radius as i32 / 2, 14);
            let zeros = || {
                Rows::zeros(
                    -3,
                    out_rows.0,
                    width,
                    out_rows.1,
                    input.channels.clone(),
                    valid,
                )
            };
            let (mut ours, mut reference) = (zeros(), zeros());
            let (top, height) = (ours.y, ours.height);
            for mut band in ours.bands(top, height) {
                op.compute(1, &[&input], &mut band).unwrap();
            }
            exact(&op, &input, &mut reference);
            for (c, channel) in ours.channels.iter().enumerate() {
                let n = ours.width * ours.height;
                let (mut a, mut b) = (vec![0.0f32; n], vec![0.0f32; n]);
                ours.planes[c].read_f32(0..n, &mut a);
                reference.planes[c].read_f32(0..n, &mut b);
                for (i, (a, b)) in a.iter().zip(&b).enumerate() {
                    assert!(
                        close(*a, *b),
                        "{aperture:?} R {max_radius} focus {focus} {:?} pixel {i}: {a} vs {b}",
                        channel.name
                    );
                    if *b != 0.0 {
                        worst = worst.max((a - b).abs() / b.abs());
                    }
                }
            }
        }
    }
    eprintln!("largest relative difference from the exact gather: {worst:e}");
}

#[test]
fn a_span_of_the_footprint_is_every_offset_within_the_radius() {
    for aperture in [
        Aperture::Disc,
        Aperture::Polygon(3),
        Aperture::Polygon(6),
        Aperture::Polygon(7),
    ] {
        let reach = 24;
        let footprints = Footprints::new(aperture, reach);
        let mut rng = Lcg(7);
        for _ in 0..200 {
            let r = reach as f32 * rng.next();
            for dy in -reach..=reach {
                let span = footprints.span(r, dy);
                for dx in -reach..=reach {
                    let inside = footprints.need(dx, dy) <= r;
                    assert_eq!(
                        inside,
                        dx >= span.lo && dx <= span.hi,
                        "{aperture:?} r {r} ({dx}, {dy})"
                    );
                }
            }
        }
    }
}

#[test]
fn the_circle_of_confusion_is_scale_times_the_focus_error_clamped() {
    let op = Defocus {
        focus: 10.0,
        scale: 8.0,
        max_radius: 12,
        aperture: Aperture::Disc,
        z_channel: "Z".into(),
        layers: Default::default(),
    };
    // r = S |1 - F / Z|: in focus 0, twice as far S / 2, far away S.
    assert_eq!(op.coc(10.0), 0.0);
    assert_eq!(op.coc(20.0), 4.0);
    assert_eq!(op.coc(1e9), 8.0 * (1.0 - 10.0 / 1e9));
    // Nearer than the focus grows without bound, up to the maximum.
    assert_eq!(op.coc(5.0), 8.0);
    assert_eq!(op.coc(2.0), 12.0);
    for z in [0.0, -1.0, f32::NAN, f32::NEG_INFINITY] {
        assert_eq!(op.coc(z), 0.0, "{z}");
    }
}
