//! How much a glTF's JSON holds, counted without building it: the `gltf`
//! crate turns every JSON object into a struct of a few hundred bytes, so
//! a file within the byte limit made of millions of empty nodes (`{}`,
//! three bytes each) took gigabytes. The JSON is walked once, keeping
//! nothing, and refused as soon as it passes the bounds.

use serde::de::{DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};

/// The most JSON objects a glTF may hold (nodes, meshes, primitives,
/// accessors, materials, ...): far more than any room's scan needs (a
/// kitchen exported from CAD has thousands), few enough to build.
pub const MOST_OBJECTS: u64 = 1_000_000;

/// The most JSON values of any kind (numbers of matrices and bounds
/// included).
pub const MOST_VALUES: u64 = 20_000_000;

/// What a JSON text holds so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    pub objects: u64,
    pub values: u64,
}

/// The tally of `json`, or why it is refused: not JSON, or more than
/// [`MOST_OBJECTS`] objects or [`MOST_VALUES`] values.
pub fn tally(json: &[u8]) -> Result<Tally, String> {
    let mut tally = Tally::default();
    let mut de = serde_json::Deserializer::from_slice(json);
    Count(&mut tally)
        .deserialize(&mut de)
        .and_then(|()| de.end())
        .map_err(|e| e.to_string())?;
    Ok(tally)
}

/// Counts one value and what it holds into its tally.
struct Count<'t>(&'t mut Tally);

impl Count<'_> {
    fn one<E: serde::de::Error>(&mut self, object: bool) -> Result<(), E> {
        self.0.values += 1;
        self.0.objects += u64::from(object);
        if self.0.objects > MOST_OBJECTS {
            return Err(E::custom(format!(
                "its JSON holds more than {MOST_OBJECTS} objects (nodes, meshes, accessors, ...)"
            )));
        }
        if self.0.values > MOST_VALUES {
            return Err(E::custom(format!(
                "its JSON holds more than {MOST_VALUES} values"
            )));
        }
        Ok(())
    }
}

impl<'de> DeserializeSeed<'de> for Count<'_> {
    type Value = ();

    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<(), D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for Count<'_> {
    type Value = ();

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("JSON")
    }

    fn visit_bool<E: serde::de::Error>(mut self, _: bool) -> Result<(), E> {
        self.one(false)
    }

    fn visit_i64<E: serde::de::Error>(mut self, _: i64) -> Result<(), E> {
        self.one(false)
    }

    fn visit_u64<E: serde::de::Error>(mut self, _: u64) -> Result<(), E> {
        self.one(false)
    }

    fn visit_f64<E: serde::de::Error>(mut self, _: f64) -> Result<(), E> {
        self.one(false)
    }

    fn visit_str<E: serde::de::Error>(mut self, _: &str) -> Result<(), E> {
        self.one(false)
    }

    fn visit_unit<E: serde::de::Error>(mut self) -> Result<(), E> {
        self.one(false)
    }

    fn visit_seq<A: SeqAccess<'de>>(mut self, mut seq: A) -> Result<(), A::Error> {
        self.one(false)?;
        while seq.next_element_seed(Count(&mut *self.0))?.is_some() {}
        Ok(())
    }

    fn visit_map<A: MapAccess<'de>>(mut self, mut map: A) -> Result<(), A::Error> {
        self.one(true)?;
        while map.next_key_seed(Count(&mut *self.0))?.is_some() {
            map.next_value_seed(Count(&mut *self.0))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_document_is_counted_whole() {
        let t = tally(br#"{"nodes": [{}, {"mesh": 0}], "scene": 0}"#).unwrap();
        // The root, two nodes; values: the root, its two keys, the array,
        // two nodes, the key `mesh` and its 0, and the scene's 0.
        assert_eq!(
            t,
            Tally {
                objects: 3,
                values: 9
            }
        );
    }

    #[test]
    fn millions_of_empty_objects_are_refused_as_soon_as_they_pass_the_bound() {
        let many = format!("[{}{{}}]", "{},".repeat(MOST_OBJECTS as usize));
        let why = tally(many.as_bytes()).unwrap_err();
        assert!(why.contains("more than 1000000 objects"), "{why}");
        let fewer = format!("[{}{{}}]", "{},".repeat(MOST_OBJECTS as usize - 1));
        assert_eq!(tally(fewer.as_bytes()).unwrap().objects, MOST_OBJECTS);
    }

    #[test]
    fn what_is_not_json_is_refused() {
        assert!(tally(b"{\"nodes\": [").is_err());
        assert!(tally(b"{} trailing").is_err());
    }
}
