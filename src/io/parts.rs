//! Choosing the part of a multi-part file an input reads: `file.exr:PART`
//! (a name or an index), `--part`, or the part of a view (`--view left`).

use super::reader::ExrFile;
use crate::error::Result;

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
/// the one whose `view` attribute is `view`, else the first.
pub fn choose_part(file: &ExrFile, part: Option<&str>, view: Option<&str>) -> Result<usize> {
    let headers = &file.meta.headers;
    let names = || {
        headers
            .iter()
            .enumerate()
            .map(|(i, h)| match &h.own_attributes.layer_name {
                Some(name) => format!("{i} ({name})"),
                None => i.to_string(),
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    if let Some(part) = part {
        let by_name = headers.iter().position(|h| {
            h.own_attributes
                .layer_name
                .as_ref()
                .is_some_and(|n| n.eq(part))
        });
        let by_index = part.parse::<usize>().ok().filter(|&i| i < headers.len());
        return by_name
            .or(by_index)
            .ok_or_else(|| file.error(format!("has no part '{part}' (parts: {})", names())));
    }
    if let Some(view) = view.filter(|_| headers.len() > 1) {
        return headers
            .iter()
            .position(|h| {
                h.own_attributes
                    .view_name
                    .as_ref()
                    .is_some_and(|n| n.eq(view))
            })
            .ok_or_else(|| {
                file.error(format!("has no part of view '{view}' (parts: {})", names()))
            });
    }
    Ok(0)
}

#[cfg(test)]
mod tests {
    use super::split_part;

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
