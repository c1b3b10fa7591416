//! Which channels an operation composites: layers (`diffuse.R`), views
//! (`left.R`) and their alphas. See specs/ops.md, "Layers and views".

use crate::io::rows::Rows;
use crate::io::text::Utf8Text;
use exr::meta::attribute::ChannelDescription;

/// The colour channels of a layer; its other channels (Z, u, v, mask...)
/// pass through.
pub const COLOUR: [&str; 3] = ["R", "G", "B"];

/// The layers an operation works on, as the command line gives them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Selection {
    /// Layer names; empty means the unnamed layer (plain R, G, B, A).
    pub layers: Vec<String>,
    /// Every layer both inputs have (`--all-layers`).
    pub all: bool,
    /// A view of a multi-view file (`left`): its channels `left.R` or
    /// `layer.left.R` where the file has them, else the default view's.
    pub view: Option<String>,
}

/// One selected layer, resolved against the channels at hand.
#[derive(Clone, Debug, PartialEq)]
pub struct Layer {
    /// Prefix of its channel names: "", "diffuse.", "left." or "diffuse.left.".
    pub prefix: String,
    /// Where its alpha is read, first found first: its own `A`, the view's,
    /// the unnamed `A`; with none of them, alpha is 1 inside the data window.
    pub alphas: Vec<String>,
}

impl Layer {
    pub fn colours(&self) -> impl Iterator<Item = String> + '_ {
        COLOUR.iter().map(|c| format!("{}{c}", self.prefix))
    }

    pub fn alpha_channel(&self) -> String {
        format!("{}A", self.prefix)
    }

    /// Alpha of absolute row `y` of `rows` as f32 (see `alphas`), from
    /// sample offset `from` on, as many as `out` holds.
    pub fn read_alpha(&self, rows: &Rows, y: i32, from: usize, out: &mut [f32]) {
        match self.alphas.iter().find_map(|n| rows.channel_index(n)) {
            Some(a) => {
                let start = rows.row_range(y).start + from;
                rows.planes[a].read_f32(start..start + out.len(), out)
            }
            None => rows.implicit_alpha(y, from, out),
        }
    }
}

fn has(channels: &[&[ChannelDescription]], name: &str) -> bool {
    channels
        .iter()
        .any(|list| list.iter().any(|c| c.name.is(name)))
}

fn has_prefix(channels: &[&[ChannelDescription]], prefix: &str) -> bool {
    channels.iter().any(|list| {
        list.iter()
            .map(|c| c.name.utf8())
            .any(|name| name.starts_with(prefix) && prefix.len() < name.len())
    })
}

/// The layer part of a channel name ("diffuse" for "diffuse.R", "" for "R").
fn layer_of(name: &str) -> &str {
    name.rsplit_once('.').map_or("", |(layer, _)| layer)
}

impl Selection {
    /// The layers selected among `inputs`' channels (for one input: its
    /// own; for a merge: A's and B's).
    pub fn resolve(&self, inputs: &[&[ChannelDescription]]) -> Vec<Layer> {
        let view_prefix = |layer: &str| -> Option<String> {
            let view = self.view.as_ref()?;
            let prefix = if layer.is_empty() {
                format!("{view}.")
            } else {
                format!("{layer}.{view}.")
            };
            has_prefix(inputs, &prefix).then_some(prefix)
        };
        let names: Vec<String> = if self.all {
            Self::common_layers(inputs)
        } else if self.layers.is_empty() {
            vec![String::new()]
        } else {
            self.layers.clone()
        };
        let view_alpha = view_prefix("").map(|p| format!("{p}A"));
        let mut layers: Vec<Layer> = names
            .iter()
            .map(|name| {
                let prefix = view_prefix(name).unwrap_or_else(|| match name.as_str() {
                    "" => String::new(),
                    _ => format!("{name}."),
                });
                let mut alphas = vec![format!("{prefix}A")];
                alphas.extend(view_alpha.clone());
                alphas.push("A".into());
                alphas.dedup();
                Layer { prefix, alphas }
            })
            .collect();
        layers.dedup_by(|a, b| a.prefix == b.prefix);
        layers
    }

    /// Layers with a colour channel in every input, in name order ("" first);
    /// view channels count as layers of their own ("left" for `left.R`).
    fn common_layers(inputs: &[&[ChannelDescription]]) -> Vec<String> {
        let colour_layers = |list: &[ChannelDescription]| -> Vec<String> {
            list.iter()
                .map(|c| c.name.utf8())
                .filter(|n| COLOUR.iter().any(|c| n.rsplit('.').next() == Some(c)))
                .map(|n| layer_of(&n).to_string())
                .collect()
        };
        let mut names = colour_layers(inputs[0]);
        names.retain(|n| {
            inputs[1..]
                .iter()
                .all(|list| colour_layers(list).contains(n))
        });
        names.sort();
        names.dedup();
        names
    }
}

impl Selection {
    /// The selected layers' R, G, B and A that `list` has: what a one-input
    /// filter works on.
    pub fn filtered(&self, list: &[ChannelDescription]) -> Vec<String> {
        self.resolve(&[list])
            .iter()
            .flat_map(|l| l.colours().chain([l.alpha_channel()]).collect::<Vec<_>>())
            .filter(|n| has(&[list], n))
            .collect()
    }

    /// Like `check`, and also that `list` has each of `needed` (a depth or
    /// vector channel), naming the first one missing as `what`.
    pub fn check_with(
        &self,
        list: &[ChannelDescription],
        needed: &[&str],
        what: &str,
    ) -> Result<(), String> {
        if let Some(missing) = needed.iter().find(|n| !has(&[list], n)) {
            return Err(format!("no {what} channel '{missing}'"));
        }
        self.check(&[list])
    }

    /// An error naming the first selected layer that no input has, with the
    /// layers they do have.
    pub fn check(&self, inputs: &[&[ChannelDescription]]) -> Result<(), String> {
        for layer in self.resolve(inputs) {
            let present =
                layer.colours().any(|c| has(inputs, &c)) || has(inputs, &layer.alpha_channel());
            if !present {
                let mut found: Vec<String> = Self::common_layers(&inputs[..1]);
                found
                    .iter_mut()
                    .filter(|n| n.is_empty())
                    .for_each(|n| *n = "(unnamed)".into());
                let name = layer.prefix.trim_end_matches('.');
                let name = if name.is_empty() { "(unnamed)" } else { name };
                return Err(format!(
                    "layer '{name}' not found (layers with colour: {})",
                    found.join(", ")
                ));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exr::meta::attribute::SampleType;

    fn list(names: &[&str]) -> Vec<ChannelDescription> {
        names
            .iter()
            .map(|n| ChannelDescription::named(*n, SampleType::F16))
            .collect()
    }

    fn selection(layers: &[&str], all: bool, view: Option<&str>) -> Selection {
        Selection {
            layers: layers.iter().map(|l| l.to_string()).collect(),
            all,
            view: view.map(str::to_string),
        }
    }

    fn prefixes(layers: &[Layer]) -> Vec<&str> {
        layers.iter().map(|l| l.prefix.as_str()).collect()
    }

    #[test]
    fn layers_resolve_to_prefixes_with_their_alpha_fallbacks() {
        let file = list(&[
            "A",
            "B",
            "G",
            "R",
            "diffuse.B",
            "diffuse.G",
            "diffuse.R",
            "Z",
        ]);
        let unnamed = selection(&[], false, None).resolve(&[&file]);
        assert_eq!(
            unnamed,
            [Layer {
                prefix: "".into(),
                alphas: vec!["A".into()]
            }]
        );
        let diffuse = selection(&["diffuse"], false, None).resolve(&[&file]);
        assert_eq!(diffuse[0].prefix, "diffuse.");
        assert_eq!(diffuse[0].alphas, ["diffuse.A", "A"]);
        assert_eq!(
            diffuse[0].colours().collect::<Vec<_>>(),
            ["diffuse.R", "diffuse.G", "diffuse.B"]
        );
        assert!(selection(&["specular"], false, None)
            .check(&[&file])
            .is_err());
        let message = selection(&["specular"], false, None)
            .check(&[&file])
            .unwrap_err();
        assert_eq!(
            message,
            "layer 'specular' not found (layers with colour: (unnamed), diffuse)"
        );
    }

    #[test]
    fn all_layers_are_those_with_colour_in_every_input() {
        let a = list(&["R", "diffuse.R", "spec.G", "Z"]);
        let b = list(&["G", "diffuse.B", "mask.A"]);
        let all = selection(&[], true, None).resolve(&[&a, &b]);
        assert_eq!(prefixes(&all), ["", "diffuse."]);
    }

    #[test]
    fn a_view_reads_its_channels_where_the_file_has_them_else_the_default_view() {
        let stereo = list(&[
            "A",
            "B",
            "G",
            "R",
            "left.A",
            "left.B",
            "left.G",
            "left.R",
            "diffuse.left.R",
            "diffuse.R",
        ]);
        let left = selection(&[], false, Some("left")).resolve(&[&stereo]);
        assert_eq!(left[0].prefix, "left.");
        assert_eq!(left[0].alphas, ["left.A", "A"]);
        let diffuse = selection(&["diffuse"], false, Some("left")).resolve(&[&stereo]);
        assert_eq!(diffuse[0].prefix, "diffuse.left.");
        assert_eq!(diffuse[0].alphas, ["diffuse.left.A", "left.A", "A"]);
        // The default view (`right` here) has no view name in its channels.
        let right = selection(&["diffuse"], false, Some("right")).resolve(&[&stereo]);
        assert_eq!(prefixes(&right), ["diffuse."]);
        // Filtered: the selected R, G, B, A the file has.
        let filtered = selection(&["diffuse"], false, Some("left")).filtered(&stereo);
        assert_eq!(filtered, ["diffuse.left.R"]);
    }
}
