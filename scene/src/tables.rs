//! A struct is read from a table (a TOML table, a JSON object, a dict), never from an array.
//!
//! serde's derive also reads a struct from a sequence of its fields in their declared order, so
//! `cue = [2.0, 0.1]` was read as a strike of speed 2.0 and aim 0.1 (and a reordering of the
//! struct's fields would have changed what it meant). [`Tables`] wraps a deserializer so that
//! every struct within it, at any depth, refuses a sequence with serde's own "invalid type"
//! error; everything else passes through unchanged. Arrays where the formats want arrays
//! (`pos = [x, y]`, `balls = [...]`) are sequences of numbers or of tables and still read.

use serde::de::{
    self, DeserializeSeed, Deserializer, EnumAccess, MapAccess, SeqAccess, Unexpected,
    VariantAccess, Visitor,
};
use std::fmt;

/// A deserializer whose structs are read only from maps (see the module's documentation).
pub struct Tables<D>(pub D);

/// A visitor, passed on with every value it is handed wrapped; `structure`: it reads a struct,
/// so a sequence is refused.
struct Visit<V> {
    inner: V,
    structure: bool,
}

impl<V> Visit<V> {
    fn value(inner: V) -> Self {
        Visit {
            inner,
            structure: false,
        }
    }

    fn structure(inner: V) -> Self {
        Visit {
            inner,
            structure: true,
        }
    }
}

/// A seq, map, enum or variant access, or a seed, whose values are deserialized through
/// [`Tables`].
struct Access<A>(A);

/// Deserializer methods taking only a visitor.
macro_rules! forward_deserialize {
    ($($method:ident),* $(,)?) => {$(
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, D::Error> {
            self.0.$method(Visit::value(visitor))
        }
    )*};
}

impl<'de, D: Deserializer<'de>> Deserializer<'de> for Tables<D> {
    type Error = D::Error;

    forward_deserialize!(
        deserialize_any,
        deserialize_bool,
        deserialize_i8,
        deserialize_i16,
        deserialize_i32,
        deserialize_i64,
        deserialize_i128,
        deserialize_u8,
        deserialize_u16,
        deserialize_u32,
        deserialize_u64,
        deserialize_u128,
        deserialize_f32,
        deserialize_f64,
        deserialize_char,
        deserialize_str,
        deserialize_string,
        deserialize_bytes,
        deserialize_byte_buf,
        deserialize_option,
        deserialize_unit,
        deserialize_seq,
        deserialize_map,
        deserialize_identifier,
        deserialize_ignored_any,
    );

    fn deserialize_unit_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0.deserialize_unit_struct(name, Visit::value(visitor))
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0
            .deserialize_newtype_struct(name, Visit::value(visitor))
    }

    fn deserialize_tuple<V: Visitor<'de>>(
        self,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0.deserialize_tuple(len, Visit::value(visitor))
    }

    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        len: usize,
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0
            .deserialize_tuple_struct(name, len, Visit::value(visitor))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0
            .deserialize_struct(name, fields, Visit::structure(visitor))
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        name: &'static str,
        variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, D::Error> {
        self.0
            .deserialize_enum(name, variants, Visit::value(visitor))
    }

    fn is_human_readable(&self) -> bool {
        self.0.is_human_readable()
    }
}

/// Visitor methods handed a plain value, passed on as they are.
macro_rules! forward_visit {
    ($($method:ident($ty:ty)),* $(,)?) => {$(
        fn $method<E: de::Error>(self, v: $ty) -> Result<V::Value, E> {
            self.inner.$method(v)
        }
    )*};
}

impl<'de, V: Visitor<'de>> Visitor<'de> for Visit<V> {
    type Value = V::Value;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        self.inner.expecting(f)
    }

    forward_visit!(
        visit_bool(bool),
        visit_i8(i8),
        visit_i16(i16),
        visit_i32(i32),
        visit_i64(i64),
        visit_i128(i128),
        visit_u8(u8),
        visit_u16(u16),
        visit_u32(u32),
        visit_u64(u64),
        visit_u128(u128),
        visit_f32(f32),
        visit_f64(f64),
        visit_char(char),
        visit_str(&str),
        visit_borrowed_str(&'de str),
        visit_string(String),
        visit_bytes(&[u8]),
        visit_borrowed_bytes(&'de [u8]),
        visit_byte_buf(Vec<u8>),
    );

    fn visit_none<E: de::Error>(self) -> Result<V::Value, E> {
        self.inner.visit_none()
    }

    fn visit_unit<E: de::Error>(self) -> Result<V::Value, E> {
        self.inner.visit_unit()
    }

    fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<V::Value, D::Error> {
        self.inner.visit_some(Tables(d))
    }

    fn visit_newtype_struct<D: Deserializer<'de>>(self, d: D) -> Result<V::Value, D::Error> {
        self.inner.visit_newtype_struct(Tables(d))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<V::Value, A::Error> {
        if self.structure {
            return Err(de::Error::invalid_type(Unexpected::Seq, &self));
        }
        self.inner.visit_seq(Access(seq))
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<V::Value, A::Error> {
        self.inner.visit_map(Access(map))
    }

    fn visit_enum<A: EnumAccess<'de>>(self, data: A) -> Result<V::Value, A::Error> {
        self.inner.visit_enum(Access(data))
    }
}

impl<'de, S: DeserializeSeed<'de>> DeserializeSeed<'de> for Access<S> {
    type Value = S::Value;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<S::Value, D::Error> {
        self.0.deserialize(Tables(d))
    }
}

impl<'de, A: SeqAccess<'de>> SeqAccess<'de> for Access<A> {
    type Error = A::Error;

    fn next_element_seed<T: DeserializeSeed<'de>>(
        &mut self,
        seed: T,
    ) -> Result<Option<T::Value>, A::Error> {
        self.0.next_element_seed(Access(seed))
    }

    fn size_hint(&self) -> Option<usize> {
        self.0.size_hint()
    }
}

impl<'de, A: MapAccess<'de>> MapAccess<'de> for Access<A> {
    type Error = A::Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        self.0.next_key_seed(Access(seed))
    }

    fn next_value_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<T::Value, A::Error> {
        self.0.next_value_seed(Access(seed))
    }

    fn size_hint(&self) -> Option<usize> {
        self.0.size_hint()
    }
}

impl<'de, A: EnumAccess<'de>> EnumAccess<'de> for Access<A> {
    type Error = A::Error;
    type Variant = Access<A::Variant>;

    fn variant_seed<T: DeserializeSeed<'de>>(
        self,
        seed: T,
    ) -> Result<(T::Value, Self::Variant), A::Error> {
        let (value, variant) = self.0.variant_seed(Access(seed))?;
        Ok((value, Access(variant)))
    }
}

impl<'de, A: VariantAccess<'de>> VariantAccess<'de> for Access<A> {
    type Error = A::Error;

    fn unit_variant(self) -> Result<(), A::Error> {
        self.0.unit_variant()
    }

    fn newtype_variant_seed<T: DeserializeSeed<'de>>(self, seed: T) -> Result<T::Value, A::Error> {
        self.0.newtype_variant_seed(Access(seed))
    }

    fn tuple_variant<V: Visitor<'de>>(self, len: usize, visitor: V) -> Result<V::Value, A::Error> {
        self.0.tuple_variant(len, Visit::value(visitor))
    }

    fn struct_variant<V: Visitor<'de>>(
        self,
        fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, A::Error> {
        self.0.struct_variant(fields, Visit::structure(visitor))
    }
}

#[cfg(test)]
mod tests {
    use super::Tables;
    use serde::Deserialize;

    #[derive(Debug, Deserialize, PartialEq)]
    #[serde(deny_unknown_fields)]
    struct Strike {
        speed: f64,
        aim: f64,
    }

    #[derive(Debug, Deserialize, PartialEq)]
    struct Scene {
        cue: Option<Strike>,
        pos: Vec<[f64; 2]>,
        strikes: Vec<Strike>,
    }

    fn json(text: &str) -> Result<Scene, String> {
        let mut de = serde_json::Deserializer::from_str(text);
        Scene::deserialize(Tables(&mut de)).map_err(|e| e.to_string())
    }

    #[test]
    fn a_struct_from_a_table_reads_and_from_an_array_is_refused_at_any_depth() {
        let ok = r#"{"cue": {"speed": 2, "aim": 0.1}, "pos": [[1, 2]], "strikes": [{"speed": 1, "aim": 0}]}"#;
        let s = json(ok).unwrap();
        assert_eq!(
            s.cue,
            Some(Strike {
                speed: 2.0,
                aim: 0.1
            })
        );
        assert_eq!(s.pos, vec![[1.0, 2.0]]);
        // The same without the wrapper: serde's derive reads the arrays by position.
        let positional = r#"{"cue": [2, 0.1], "pos": [], "strikes": [[1, 0]]}"#;
        let plain: Scene = serde_json::from_str(positional).unwrap();
        assert_eq!(
            plain.cue,
            Some(Strike {
                speed: 2.0,
                aim: 0.1
            })
        );
        for text in [
            r#"{"cue": [2, 0.1], "pos": [], "strikes": []}"#,
            r#"{"cue": null, "pos": [], "strikes": [[1, 0]]}"#,
            r#"[null, [], []]"#,
        ] {
            let e = json(text).unwrap_err();
            assert!(
                e.contains("invalid type: sequence, expected struct"),
                "{text}: {e}"
            );
        }
    }

    #[test]
    fn toml_tables_read_and_an_inline_array_for_a_table_is_refused() {
        let read = |text: &str| {
            let de = toml::de::Deserializer::parse(text).unwrap();
            Scene::deserialize(Tables(de)).map_err(|e| e.to_string())
        };
        let s = read("pos = [[1.0, 2.0]]\nstrikes = []\n[cue]\nspeed = 2.0\naim = 0.1\n").unwrap();
        assert_eq!(
            s.cue,
            Some(Strike {
                speed: 2.0,
                aim: 0.1
            })
        );
        let e = read("cue = [2.0, 0.1]\npos = []\nstrikes = []\n").unwrap_err();
        assert!(e.contains("invalid type: sequence, expected struct"), "{e}");
    }
}
