//! Choosing the part of a multi-part file an input reads: `file.exr:PART`
//! (a name or an index), `--part`, or the part of a view (`--view left`).

use super::reader::ExrFile;
use crate::error::Result;
use crate::io::text::Utf8Text;

/// Splits `beauty.####.exr:left` into the path and the part. Only a suffix
/// after `.exr` counts, so paths with colons elsewhere stay whole.
pub fn split_part(text: &str) -> (&str, Option<&str>) {
    match text.rsplit_once(':') {
        Some((path, part))
            if !part.is_empty()
                && !part.contains('/')
                && path.to_ascii_lowercase().ends_with(".exr") =>
        {
            (path, Some(part))
        }
        _ => (text, None),
    }
}

/// The index of the part to read: the one named or numbered by `part`, else
/// the one of view `view`, else the first. An unknown part or view is an
/// input error listing those the file has; a file without views is the
/// same image in every view.
pub fn choose_part(file: &ExrFile, part: Option<&str>, view: Option<&str>) -> Result<usize> {
    let headers = &file.meta.headers;
    if let Some(part) = part {
        let names: Vec<String> = headers
            .iter()
            .filter_map(|h| h.own_attributes.layer_name.as_ref())
            .map(|n| n.utf8())
            .collect();
        let by_name = headers.iter().position(|h| {
            h.own_attributes
                .layer_name
                .as_ref()
                .is_some_and(|n| n.is(part))
        });
        let by_index = part.parse::<usize>().ok().filter(|&i| i < headers.len());
        let listed: Vec<String> = headers
            .iter()
            .enumerate()
            .map(|(i, h)| match &h.own_attributes.layer_name {
                Some(name) => format!("{i} ({})", name.utf8()),
                None => i.to_string(),
            })
            .collect();
        return by_name
            .or(by_index)
            .ok_or_else(|| file.error(unknown("part", part, &listed.join(", "), &names)));
    }
    let Some(view) = view else { return Ok(0) };
    let views = views(file);
    if views.is_empty() {
        return Ok(0);
    }
    if !views.iter().any(|v| v == view) {
        return Err(file.error(unknown("view", view, &views.join(", "), &views)));
    }
    // The parts whose `view` is the view hold it; a `multiView` list only
    // names the views (a multi-part file lists them in every part), so a
    // part listing it holds it only when no part is of that view. A view
    // is all its parts: its colour is read from the first of them with
    // colour, so a depth-only part ahead (`depth_left`, then `rgba_left`)
    // is not taken for the view.
    let of_view: Vec<usize> = (0..headers.len())
        .filter(|&i| {
            let name = headers[i].own_attributes.view_name.as_ref();
            name.is_some_and(|n| n.is(view))
        })
        .collect();
    let by_attribute = of_view
        .iter()
        .copied()
        .find(|&i| has_colour(&headers[i]))
        .or(of_view.first().copied());
    let by_list = || {
        headers.iter().position(|h| {
            let list = h.own_attributes.multi_view_names.as_ref();
            list.is_some_and(|list| list.iter().any(|n| n.is(view)))
        })
    };
    Ok(by_attribute.or_else(by_list).unwrap_or(0))
}

/// Whether a part has a colour channel: R, G, B or luminance Y, of any
/// layer (`diffuse.R`).
fn has_colour(header: &exr::meta::header::Header) -> bool {
    header.channels.list.iter().any(|c| {
        let name = c.name.utf8();
        let last = name.rsplit('.').next().unwrap_or_default();
        ["R", "G", "B", "Y"].contains(&last)
    })
}

/// The views of a file, in order: its parts' `view` attributes and the
/// `multiView` lists of its parts.
fn views(file: &ExrFile) -> Vec<String> {
    let mut views: Vec<String> = Vec::new();
    for header in &file.meta.headers {
        let attributes = &header.own_attributes;
        let listed = attributes.multi_view_names.iter().flatten();
        for name in attributes.view_name.iter().chain(listed) {
            let name = name.utf8();
            if !views.contains(&name) {
                views.push(name);
            }
        }
    }
    views
}

/// "no view 'centre' (views: left, right)", with a near name suggested.
pub fn unknown(what: &str, asked: &str, listed: &str, names: &[String]) -> String {
    let mut message = format!("no {what} '{asked}' ({what}s: {listed})");
    if let Some(near) = nearest(asked, names) {
        message += &format!("; did you mean '{near}'?");
    }
    message
}

/// The name of `names` closest to `asked`, if a typo away: the same but for
/// case, or at most a third of its letters changed, added, removed or swapped.
fn nearest<'a>(asked: &str, names: &'a [String]) -> Option<&'a str> {
    let asked = asked.to_lowercase();
    names
        .iter()
        .map(|name| (edits(&asked, &name.to_lowercase()), name.as_str()))
        .filter(|&(distance, name)| distance <= (name.chars().count() / 3).max(1))
        .min_by_key(|&(distance, _)| distance)
        .map(|(_, name)| name)
}

/// Optimal string alignment distance: insertions, deletions, substitutions
/// and swaps of neighbours.
fn edits(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let width = b.len() + 1;
    let mut d: Vec<usize> = vec![0; (a.len() + 1) * width];
    for i in 0..=a.len() {
        for j in 0..=b.len() {
            d[i * width + j] = if i == 0 || j == 0 {
                i + j
            } else {
                let cost = usize::from(a[i - 1] != b[j - 1]);
                let mut best = (d[(i - 1) * width + j] + 1)
                    .min(d[i * width + j - 1] + 1)
                    .min(d[(i - 1) * width + j - 1] + cost);
                if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                    best = best.min(d[(i - 2) * width + j - 2] + 1);
                }
                best
            };
        }
    }
    d[a.len() * width + b.len()]
}

#[cfg(test)]
mod tests {
    use super::{nearest, split_part};

    #[test]
    fn suggests_only_near_names() {
        let names: Vec<String> = ["left", "right", "rgba_right"].map(String::from).into();
        assert_eq!(nearest("rihgt", &names), Some("right"));
        assert_eq!(nearest("LEFT", &names), Some("left"));
        assert_eq!(nearest("rgba_rihgt", &names), Some("rgba_right"));
        assert_eq!(nearest("centre", &names), None);
        assert_eq!(nearest("2", &names), None);
    }

    #[test]
    fn splits_only_a_suffix_after_exr() {
        assert_eq!(split_part("a.exr:left"), ("a.exr", Some("left")));
        assert_eq!(split_part("shot.####.EXR:2"), ("shot.####.EXR", Some("2")));
        assert_eq!(split_part("a.exr"), ("a.exr", None));
        assert_eq!(split_part("c:/x.exr"), ("c:/x.exr", None));
        assert_eq!(split_part("dir:1/a.exr"), ("dir:1/a.exr", None));
        assert_eq!(split_part("a.exr:"), ("a.exr:", None));
    }
}
