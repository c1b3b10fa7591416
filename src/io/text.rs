//! OpenEXR's names and strings (channel and part names, string attributes)
//! are bytes, UTF-8 in practice: OpenEXR's tools and Python module show and
//! write them so. The exr crate's `Text` reads each byte as a Latin-1
//! character (`Display`, `eq`) and refuses other characters (`From<&str>`),
//! so every conversion between a `Text` and a Rust string goes through here:
//! UTF-8 both ways, bytes that are not UTF-8 shown escaped as `\xNN` (never
//! silently changed: the bytes written are always the `Text`'s own).

use exr::meta::attribute::Text;

pub trait Utf8Text {
    /// The text as UTF-8, any byte outside a valid sequence as `\xNN`.
    fn utf8(&self) -> String;
    /// Whether the text reads as `name` (`utf8`'s string).
    fn is(&self, name: &str) -> bool;
}

impl Utf8Text for Text {
    fn utf8(&self) -> String {
        let mut out = String::new();
        for chunk in self.bytes().utf8_chunks() {
            out.push_str(chunk.valid());
            for byte in chunk.invalid() {
                out.push_str(&format!("\\x{byte:02x}"));
            }
        }
        out
    }

    fn is(&self, name: &str) -> bool {
        match std::str::from_utf8(self.bytes()) {
            Ok(text) => text == name,
            Err(_) => self.utf8() == name,
        }
    }
}

/// `name`'s UTF-8 bytes as a `Text`.
pub fn text(name: &str) -> Text {
    Text::from_slice_unchecked(name.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_both_ways_and_other_bytes_escaped() {
        let name = text("Ü日本");
        assert_eq!(name.bytes(), "Ü日本".as_bytes());
        assert_eq!(name.utf8(), "Ü日本");
        assert!(name.is("Ü日本") && !name.is("Ã\u{9c}"));
        let latin1 = Text::from_slice_unchecked(b"v\xe4rde");
        assert_eq!(latin1.utf8(), "v\\xe4rde");
        assert!(latin1.is("v\\xe4rde"));
    }
}
