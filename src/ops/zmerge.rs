//! Depth-aware merge of n inputs: per pixel, the samples are put in depth
//! order (nearest first; transparent ones never in front) and composited
//! front to back with `over`. specs/ops.md, "zmerge".

use super::declare::{input, params, Operation};
use crate::engine::graph::Op;
use crate::io::rows::{Rows, RowsMut};
use crate::io::text::Utf8Text;
use exr::meta::attribute::ChannelDescription;

pub const ZMERGE: Operation = Operation {
    name: "zmerge",
    about: "Depth-aware merge: per pixel the nearer sample goes over the farther (alpha 0 \
            never in front); Z becomes the nearer depth",
    inputs: &[input(
        "inputs",
        "Two or more inputs; the last one's header and other channels are kept",
    )],
    repeats: true,
    params: Params::PARAMS,
    layers: false,
    straight: false,
    header: None,
    build: |args, graph, inputs| {
        let z_channel = Params::read(args)?.z_channel;
        Ok(graph.add(ZMerge { z_channel }, inputs))
    },
    measure: None,
};

params! {
    pub struct Params {
        /// The depth channel.
        z_channel: String = "Z",
    }
}

const COLOURS: [&str; 3] = ["R", "G", "B"];

#[derive(Debug)]
pub struct ZMerge {
    pub z_channel: String,
}

impl ZMerge {
    /// The order the inputs composite in at one pixel: by depth, nearest
    /// first; samples with alpha 0 after all others; ties keep input order.
    fn order(depths: &[f32], alphas: &[f32], order: &mut Vec<usize>) {
        order.clear();
        order.extend(0..depths.len());
        order.sort_by(|&i, &j| {
            let key = |k: usize| (alphas[k] == 0.0, depths[k]);
            let (a, b) = (key(i), key(j));
            a.0.cmp(&b.0).then(a.1.total_cmp(&b.1))
        });
    }
}

impl Op for ZMerge {
    /// The last input's channels, plus R, G, B, A, Z that only others have.
    fn channels(&self, inputs: &[&[ChannelDescription]]) -> Vec<ChannelDescription> {
        let last = inputs[inputs.len() - 1];
        let mut out = last.to_vec();
        for name in COLOURS.iter().chain(&["A", self.z_channel.as_str()]) {
            if out.iter().any(|c| c.name.is(name)) {
                continue;
            }
            if let Some(c) = inputs
                .iter()
                .find_map(|list| list.iter().find(|c| c.name.is(name)))
            {
                out.push(c.clone());
            }
        }
        out.sort_by(|a, b| a.name.bytes().cmp(b.name.bytes()));
        out
    }

    fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        match inputs
            .iter()
            .position(|list| !list.iter().any(|c| c.name.is(self.z_channel.as_str())))
        {
            Some(i) => Err(format!(
                "input {} has no depth channel '{}'",
                i + 1,
                self.z_channel
            )),
            None => Ok(()),
        }
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let n = inputs.len();
        let w = out.width;
        let columns = out.valid_columns();
        let read = |rows: &Rows, name: &str, y: i32, buffer: &mut Vec<f32>| {
            buffer.resize(w, 0.0);
            match rows.channel_index(name) {
                Some(c) => rows.planes[c].read_f32(rows.row_range(y), buffer),
                None => buffer.fill(0.0),
            }
        };
        let mut depth = vec![Vec::new(); n];
        let mut alpha = vec![Vec::new(); n];
        let mut colour = vec![vec![Vec::new(); n]; COLOURS.len()];
        let mut order = Vec::with_capacity(n);
        let (mut d, mut a) = (vec![0.0f32; n], vec![0.0f32; n]);
        let mut result = vec![vec![0.0f32; w]; COLOURS.len() + 2];
        for y in out.valid_rows() {
            for (i, rows) in inputs.iter().enumerate() {
                read(rows, &self.z_channel, y, &mut depth[i]);
                match rows.channel_index("A") {
                    Some(c) => {
                        alpha[i].resize(w, 0.0);
                        rows.planes[c].read_f32(rows.row_range(y), &mut alpha[i]);
                    }
                    None => {
                        alpha[i].resize(w, 0.0);
                        rows.implicit_alpha(y, 0, &mut alpha[i]);
                    }
                }
                for (k, name) in COLOURS.iter().enumerate() {
                    read(rows, name, y, &mut colour[k][i]);
                }
                // Outside its data window an input is nowhere: infinitely far.
                for x in columns.clone() {
                    let inside = y >= rows.valid.position.y()
                        && y < rows.valid.end().y()
                        && (rows.x + x as i32) >= rows.valid.position.x()
                        && (rows.x + x as i32) < rows.valid.end().x();
                    if !inside {
                        depth[i][x] = f32::INFINITY;
                    }
                }
            }
            for x in columns.clone() {
                for i in 0..n {
                    (d[i], a[i]) = (depth[i][x], alpha[i][x]);
                }
                Self::order(&d, &a, &mut order);
                // Front to back: C += (1 - α) c_i, α += (1 - α) α_i.
                let (mut acc, mut coverage) = ([0.0f32; 3], 0.0f32);
                for &i in &order {
                    for (k, c) in acc.iter_mut().enumerate() {
                        *c += (1.0 - coverage) * colour[k][i][x];
                    }
                    coverage += (1.0 - coverage) * a[i];
                }
                for k in 0..3 {
                    result[k][x] = acc[k];
                }
                result[3][x] = coverage;
                // The nearest depth that shows; the last input's where none does.
                result[4][x] = match order.first() {
                    Some(&i) if a[i] != 0.0 => d[i],
                    _ => depth[n - 1][x],
                };
            }
            let range = out.row_range(y);
            let dst = range.start + columns.start..range.start + columns.end;
            for (c, channel) in out.channels.iter().enumerate() {
                let name = channel.name.utf8();
                let computed = COLOURS
                    .iter()
                    .chain(&["A", self.z_channel.as_str()])
                    .position(|n| *n == name);
                match computed {
                    Some(k) => out.planes[c].write_f32(dst.clone(), &result[k][columns.clone()]),
                    None => {
                        let last = inputs[n - 1];
                        let s = last.channel_index(&name).expect("the last input's channel");
                        out.planes[c]
                            .bytes_mut(range.clone())
                            .copy_from_slice(last.planes[s].bytes(last.row_range(y)));
                    }
                }
            }
        }
        Ok(())
    }
}
