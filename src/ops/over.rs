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
            fg.alpha_f32(y, &mut fa);
            bg.alpha_f32(y, &mut ba);
            let dst = out.row_range(y);
            for c in 0..out.channels.len() {
                let name = out.channels[c].name.to_string();
                if name == "A" {
                    for x in 0..w {
                        f[x] = fa[x] + (1.0 - fa[x]) * ba[x];
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

/// C = Cf + (1 - af) Cb, in place in `f`.
fn over_premultiplied(f: &mut [f32], b: &[f32], fa: &[f32]) {
    for ((f, &b), &fa) in f.iter_mut().zip(b).zip(fa) {
        *f += (1.0 - fa) * b;
    }
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
