//! `over`: A (foreground) over B (background). See specs/ops.md.

use crate::engine::graph::Op;
use crate::engine::strip::Rows;
use exr::meta::attribute::ChannelDescription;

const COLOUR: [&str; 3] = ["R", "G", "B"];

pub struct Over {
    /// Inputs are unpremultiplied: premultiply, composite, unpremultiply.
    pub straight: bool,
}

impl Op for Over {
    /// B's channels, plus any of R, G, B, A that only A has (with A's type).
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let (fg, bg) = (inputs[0], inputs[1]);
        let mut out = bg.to_vec();
        for name in ["R", "G", "B", "A"] {
            let in_bg = bg.iter().any(|c| c.name.eq(name));
            if let Some(c) = fg.iter().find(|c| c.name.eq(name)).filter(|_| !in_bg) {
                out.push(c.clone());
            }
        }
        out.sort_by(|a, b| a.name.bytes().cmp(b.name.bytes()));
        out
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut Rows) {
        let (fg, bg) = (inputs[0], inputs[1]);
        let w = out.width;
        let mut fa = vec![0.0f32; w];
        let mut ba = vec![0.0f32; w];
        let mut f = vec![0.0f32; w];
        let mut b = vec![0.0f32; w];
        for y in out.y..out.end() {
            bg.alpha_f32(y, &mut ba);
            let dst = out.row_range(y);
            if !self.straight && transparent_black(fg, y) {
                // Nothing of A here: B's row as it is (what the formula gives).
                for c in 0..out.channels.len() {
                    match bg.channel_index(&out.channels[c].name.to_string()) {
                        Some(src) => {
                            let bytes = bg.planes[src].bytes(bg.row_range(y));
                            out.planes[c].bytes_mut(dst.clone()).copy_from_slice(bytes);
                        }
                        // An alpha only A has: B's implicit alpha; colours stay 0.
                        None if out.channels[c].name.eq("A") => {
                            out.planes[c].write_f32(dst.clone(), &ba)
                        }
                        None => {}
                    }
                }
                continue;
            }
            fg.alpha_f32(y, &mut fa);
            for c in 0..out.channels.len() {
                let name = out.channels[c].name.to_string();
                if name == "A" {
                    for x in 0..w {
                        f[x] = if fa[x] == 0.0 {
                            ba[x]
                        } else {
                            fa[x] + (1.0 - fa[x]) * ba[x]
                        };
                    }
                } else if COLOUR.contains(&name.as_str()) {
                    read_or_zero(fg, &name, y, &mut f);
                    read_or_zero(bg, &name, y, &mut b);
                    if self.straight {
                        over_straight(&mut f, &b, &fa, &ba);
                    } else {
                        over_premultiplied(&mut f, &b, &fa);
                    }
                } else {
                    // Everything else passes through from B, bit for bit.
                    let src = bg.channel_index(&name).expect("channel comes from B");
                    let bytes = bg.planes[src].bytes(bg.row_range(y));
                    out.planes[c].bytes_mut(dst.clone()).copy_from_slice(bytes);
                    continue;
                }
                out.planes[c].write_f32(dst.clone(), &f);
            }
        }
    }
}

fn read_or_zero(rows: &Rows, name: &str, y: i32, out: &mut [f32]) {
    match rows.channel_index(name) {
        Some(c) => rows.planes[c].read_f32(rows.row_range(y), out),
        None => out.fill(0.0),
    }
}

/// C = Cf + (1 - af) Cb, in place in `f`; exactly Cb where A adds nothing
/// (af = Cf = 0), which the sum gives too but for a -0 in B.
fn over_premultiplied(f: &mut [f32], b: &[f32], fa: &[f32]) {
    for ((f, &b), &fa) in f.iter_mut().zip(b).zip(fa) {
        *f = if fa == 0.0 && *f == 0.0 {
            b
        } else {
            *f + (1.0 - fa) * b
        };
    }
}

/// Whether A is transparent black across row `y`: outside its data window,
/// or with an alpha channel and every colour and alpha sample +0.
fn transparent_black(rows: &Rows, y: i32) -> bool {
    let v = rows.valid;
    if y < v.position.y() || y >= v.end().y() {
        return true;
    }
    rows.channel_index("A").is_some()
        && ["R", "G", "B", "A"]
            .iter()
            .filter_map(|n| rows.channel_index(n))
            .all(|c| {
                let bytes = rows.planes[c].bytes(rows.row_range(y));
                bytes
                    .chunks(64)
                    .all(|chunk| chunk.iter().fold(0, |acc, &b| acc | b) == 0)
            })
}

/// Premultiply both, composite, unpremultiply by the composite alpha
/// (colour 0 where that alpha is 0). With an opaque B this is
/// C = af Cf + (1 - af) Cb.
fn over_straight(f: &mut [f32], b: &[f32], fa: &[f32], ba: &[f32]) {
    for (((f, &b), &fa), &ba) in f.iter_mut().zip(b).zip(fa).zip(ba) {
        let alpha = fa + (1.0 - fa) * ba;
        let premultiplied = fa * *f + (1.0 - fa) * (ba * b);
        *f = if alpha == 0.0 {
            0.0
        } else {
            premultiplied / alpha
        };
    }
}
