//! The types OpenEXR requires of its standard attributes. OpenEXR refuses a
//! file whose `lineOrder`, `dataWindow`, `compression`... has another type;
//! the exr crate keeps such an attribute as a custom one, or drops it, and
//! reads on (and a file written from that header was one OpenEXR refuses).
//! So the raw header is checked here, before the crate parses it.

/// Each attribute OpenEXR's reader checks the type of, and that type
/// (OpenEXRCore's `check_req_attr`).
const REQUIRED: [(&str, &str); 13] = [
    ("channels", "chlist"),
    ("chunkCount", "int"),
    ("compression", "compression"),
    ("dataWindow", "box2i"),
    ("displayWindow", "box2i"),
    ("lineOrder", "lineOrder"),
    ("name", "string"),
    ("pixelAspectRatio", "float"),
    ("screenWindowCenter", "v2f"),
    ("screenWindowWidth", "float"),
    ("tiles", "tiledesc"),
    ("type", "string"),
    ("version", "int"),
];

/// Longest attribute or type name (with OpenEXR's long-names flag).
const MAX_NAME: usize = 256;

const MULTIPART_FLAG: u8 = 0x10;

/// Checks the types of the standard attributes in every header of `file`
/// (its bytes from the magic number on; only the headers are read). A header
/// too damaged to walk is left to the full parse, which reports it.
pub fn check(file: &[u8]) -> Result<(), String> {
    let multipart = file.get(5).is_some_and(|flags| flags & MULTIPART_FLAG != 0);
    let mut at = 8;
    for part in 0.. {
        while let Some((name, kind, end)) = attribute(file, at) {
            if let Some((_, wanted)) = REQUIRED.iter().find(|(n, _)| n.as_bytes() == name) {
                if kind != wanted.as_bytes() {
                    let place = if multipart {
                        format!("part {part}: ")
                    } else {
                        String::new()
                    };
                    return Err(format!(
                        "{place}attribute '{}' has type '{}' where OpenEXR requires '{wanted}'",
                        String::from_utf8_lossy(name),
                        String::from_utf8_lossy(kind)
                    ));
                }
            }
            at = end;
        }
        // The header's closing null byte; a second one ends the part list.
        at += 1;
        if !multipart || file.get(at).is_none_or(|&b| b == 0) {
            break;
        }
    }
    Ok(())
}

/// The attribute at `at`: its name, its type name and where it ends; `None`
/// at the end of a header or where the bytes do not hold an attribute.
fn attribute(file: &[u8], at: usize) -> Option<(&[u8], &[u8], usize)> {
    let text = |from: usize| -> Option<(&[u8], usize)> {
        let rest = file.get(from..)?;
        let len = rest.iter().take(MAX_NAME + 1).position(|&b| b == 0)?;
        Some((&rest[..len], from + len + 1))
    };
    let (name, after_name) = text(at)?;
    if name.is_empty() {
        return None;
    }
    let (kind, after_kind) = text(after_name)?;
    let size = file.get(after_kind..after_kind + 4)?;
    let size = usize::try_from(i32::from_le_bytes(size.try_into().ok()?)).ok()?;
    let end = (after_kind + 4).checked_add(size)?;
    (end <= file.len()).then_some((name, kind, end))
}

#[cfg(test)]
mod tests {
    use super::check;

    /// A header of `attributes` (name, type, value size), zero-filled values.
    fn header(multipart: bool, parts: &[&[(&str, &str, usize)]]) -> Vec<u8> {
        let mut bytes = vec![0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0];
        if multipart {
            bytes[5] = super::MULTIPART_FLAG;
        }
        for attributes in parts {
            for (name, kind, size) in *attributes {
                for text in [name, kind] {
                    bytes.extend_from_slice(text.as_bytes());
                    bytes.push(0);
                }
                bytes.extend_from_slice(&(*size as i32).to_le_bytes());
                bytes.extend(std::iter::repeat_n(0, *size));
            }
            bytes.push(0);
        }
        if multipart {
            bytes.push(0);
        }
        bytes
    }

    #[test]
    fn refuses_a_standard_name_of_another_type_in_any_part() {
        let good: &[(&str, &str, usize)] = &[
            ("channels", "chlist", 1),
            ("lineOrder", "lineOrder", 1),
            ("owner", "int", 4),
        ];
        assert_eq!(check(&header(false, &[good])), Ok(()));
        assert_eq!(check(&header(true, &[good, good])), Ok(()));
        let bad: &[(&str, &str, usize)] = &[("dataWindow", "v2i", 8)];
        assert_eq!(
            check(&header(true, &[good, bad])),
            Err(
                "part 1: attribute 'dataWindow' has type 'v2i' where OpenEXR requires 'box2i'"
                    .into()
            )
        );
        assert!(check(&header(false, &[bad]))
            .unwrap_err()
            .starts_with("attribute"));
    }

    #[test]
    fn leaves_damaged_headers_to_the_parse() {
        let mut bytes = header(false, &[&[("lineOrder", "int", 4)]]);
        assert!(check(&bytes).is_err());
        bytes.truncate(20);
        assert_eq!(check(&bytes), Ok(()));
        assert_eq!(check(&[]), Ok(()));
        assert_eq!(check(&[0xff; 400]), Ok(()));
    }
}
