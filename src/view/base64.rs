//! Standard base64 (RFC 4648, with padding) of the binary arrays embedded in the page.

const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/// The base64 text of `bytes`.
pub fn encode(bytes: &[u8]) -> String {
    let mut text = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let word = (u32::from(chunk[0]) << 16) | (u32::from(*chunk.get(1).unwrap_or(&0)) << 8) | u32::from(*chunk.get(2).unwrap_or(&0));
        for k in 0..4 {
            if k <= chunk.len() {
                text.push(char::from(ALPHABET[((word >> (18 - 6 * k)) & 63) as usize]));
            } else {
                text.push('=');
            }
        }
    }
    text
}

/// The bytes of base64 text written by [`encode`]; `None` for text that is not base64.
pub fn decode(text: &str) -> Option<Vec<u8>> {
    let digits = text.trim_end_matches('=').as_bytes();
    if text.len() % 4 != 0 || text.len() - digits.len() > 2 {
        return None;
    }
    let mut bytes = Vec::with_capacity(digits.len() * 3 / 4);
    let mut word = 0u32;
    for (i, &c) in digits.iter().enumerate() {
        let value = ALPHABET.iter().position(|&a| a == c)? as u32;
        word = (word << 6) | value;
        if i % 4 == 3 {
            bytes.extend_from_slice(&[(word >> 16) as u8, (word >> 8) as u8, word as u8]);
            word = 0;
        }
    }
    match digits.len() % 4 {
        2 => bytes.push((word >> 4) as u8),
        3 => bytes.extend_from_slice(&[(word >> 10) as u8, (word >> 2) as u8]),
        1 => return None,
        _ => {}
    }
    Some(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_vectors_of_rfc_4648() {
        let cases = [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foob", "Zm9vYg=="), ("fooba", "Zm9vYmE="), ("foobar", "Zm9vYmFy")];
        for (plain, coded) in cases {
            assert_eq!(encode(plain.as_bytes()), coded);
            assert_eq!(decode(coded).as_deref(), Some(plain.as_bytes()));
        }
    }

    #[test]
    fn every_byte_value_round_trips_and_bad_text_is_refused() {
        let bytes: Vec<u8> = (0..=255).collect();
        assert_eq!(decode(&encode(&bytes)), Some(bytes));
        assert_eq!(decode("Zm9"), None);
        assert_eq!(decode("Zm9v!A=="), None);
    }
}
