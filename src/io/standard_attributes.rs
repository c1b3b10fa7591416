//! The types OpenEXR requires of its standard attributes. OpenEXR refuses a
//! file whose `lineOrder`, `dataWindow`, `compression`... has another type;
//! the exr crate keeps such an attribute as a custom one, or drops it, and
//! reads on (and a file written from that header was one OpenEXR refuses).
//! So the raw header is checked here, before the crate parses it. The same
//! walk lists the attributes a file holds, for `info`.

use std::io::{BufRead, Read};

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

/// Checks the types of the standard attributes among a file's `found`
/// attributes (`attributes`). A header too damaged to walk is left to the
/// full parse, which reports it.
pub fn check(found: &[Attribute]) -> Result<(), String> {
    let multipart = found.iter().any(|a| a.part > 0);
    for Attribute {
        part, name, kind, ..
    } in found
    {
        let Some((_, wanted)) = REQUIRED.iter().find(|(n, _)| n == name) else {
            continue;
        };
        if kind != wanted {
            let place = if multipart {
                format!("part {part}: ")
            } else {
                String::new()
            };
            return Err(format!(
                "{place}attribute '{name}' has type '{kind}' where OpenEXR requires '{wanted}'"
            ));
        }
    }
    Ok(())
}

/// One attribute as the file holds it.
/// Refuses a compression code newer than the exr crate knows (OpenEXR 3.4
/// and later number theirs from 12: LJ2K, ZSTD), naming it: the crate would
/// call the attribute missing.
pub fn check_compression(file: &std::fs::File, found: &[Attribute]) -> Result<(), String> {
    use std::os::unix::fs::FileExt;
    for a in found
        .iter()
        .filter(|a| a.name == "compression" && a.size == 1)
    {
        let mut code = [0u8];
        if file.read_exact_at(&mut code, a.at).is_ok() && code[0] > HTJ2K32 {
            return Err(format!(
                "compression code {} is not supported (a method newer than HTJ2K)",
                code[0]
            ));
        }
    }
    Ok(())
}

/// The last compression code the exr crate names (OpenEXR 3.4's HTJ2K32).
const HTJ2K32: u8 = 11;

pub struct Attribute {
    pub part: usize,
    pub name: String,
    /// Its type name.
    pub kind: String,
    /// Where its value starts in the file, and its size in bytes.
    pub at: u64,
    pub size: u64,
}

/// Every attribute of every header of `file`, read from its start, in file
/// order; where the bytes stop holding attributes, those read so far.
pub fn attributes(file: &mut impl BufRead) -> Vec<Attribute> {
    let mut found = Vec::new();
    let mut start = [0u8; 8];
    if file.read_exact(&mut start).is_err() {
        return found;
    }
    let multipart = start[5] & MULTIPART_FLAG != 0;
    let mut at = start.len() as u64;
    for part in 0.. {
        loop {
            let (name, name_bytes) = match text(file) {
                Some((name, _)) if name.is_empty() => {
                    at += 1;
                    break;
                }
                Some(name) => name,
                None => return found,
            };
            let Some((kind, kind_bytes)) = text(file) else {
                return found;
            };
            at += name_bytes + kind_bytes + 4;
            let mut size = [0u8; 4];
            if file.read_exact(&mut size).is_err() {
                return found;
            }
            let Ok(size) = u64::try_from(i32::from_le_bytes(size)) else {
                return found;
            };
            let skipped = std::io::copy(&mut file.take(size), &mut std::io::sink());
            if skipped.ok() != Some(size) {
                return found;
            }
            found.push(Attribute {
                part,
                name,
                kind,
                at,
                size,
            });
            at += size;
        }
        // A header ends with a null byte (read above); in a multi-part file,
        // an empty header, one more null byte, ends the list.
        let ended = file
            .fill_buf()
            .map_or(true, |next| next.first().is_none_or(|&b| b == 0));
        if !multipart || ended {
            break;
        }
    }
    found
}

/// A null-terminated name of at most `MAX_NAME` bytes, and the bytes it
/// takes (with the null).
fn text(file: &mut impl BufRead) -> Option<(String, u64)> {
    let mut bytes = Vec::new();
    file.take(MAX_NAME as u64 + 1)
        .read_until(0, &mut bytes)
        .ok()?;
    let taken = bytes.len() as u64;
    (bytes.pop() == Some(0)).then(|| (String::from_utf8_lossy(&bytes).into_owned(), taken))
}

#[cfg(test)]
mod tests {
    use super::attributes;

    fn check(bytes: &mut &[u8]) -> Result<(), String> {
        super::check(&attributes(bytes))
    }

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
        assert_eq!(check(&mut &header(false, &[good])[..]), Ok(()));
        assert_eq!(check(&mut &header(true, &[good, good])[..]), Ok(()));
        let bad: &[(&str, &str, usize)] = &[("dataWindow", "v2i", 8)];
        assert_eq!(
            check(&mut &header(true, &[good, bad])[..]),
            Err(
                "part 1: attribute 'dataWindow' has type 'v2i' where OpenEXR requires 'box2i'"
                    .into()
            )
        );
        assert!(check(&mut &header(false, &[bad])[..])
            .unwrap_err()
            .starts_with("attribute"));
    }

    #[test]
    fn leaves_damaged_headers_to_the_parse() {
        let mut bytes = header(false, &[&[("lineOrder", "int", 4)]]);
        assert!(check(&mut &bytes[..]).is_err());
        bytes.truncate(20);
        assert_eq!(check(&mut &bytes[..]), Ok(()));
        assert_eq!(check(&mut &[][..]), Ok(()));
        assert_eq!(check(&mut &[0xffu8; 400][..]), Ok(()));
    }
}
