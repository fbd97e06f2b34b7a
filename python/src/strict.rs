//! Dicts read as the file readers read files: a Python value (dicts, lists, numbers, strings)
//! deserialized by pythonize, but a bool refused where a number is expected, as the TOML and
//! JSON readers refuse one (``invalid type: boolean `true`, expected f64``, at its key).
//! Pythonize alone reads a number from any object Python converts to one, so `True` was 1.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyTuple};
use pythonize::{Depythonizer, PythonizeError};
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Unexpected, Visitor};

type Result<T> = std::result::Result<T, PythonizeError>;

/// A Python value deserialized as a file's value would be: lists, tuples and dicts walked
/// here (so that their values are read strictly too), every other value by pythonize, with a
/// bool refused where a number is expected.
pub(crate) struct Strict<'py>(pub Bound<'py, PyAny>);

/// Methods handed to pythonize as they are.
macro_rules! leaf {
    ($($method:ident),* $(,)?) => {$(
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
            (&mut Depythonizer::from_object(&self.0)).$method(visitor)
        }
    )*};
}

/// Number methods: a bool refused, anything else handed to pythonize.
macro_rules! number {
    ($($method:ident),* $(,)?) => {$(
        fn $method<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
            self.not_bool(&visitor)?;
            (&mut Depythonizer::from_object(&self.0)).$method(visitor)
        }
    )*};
}

impl<'py> Strict<'py> {
    /// The elements of a list or tuple; None for any other value.
    fn items(&self) -> Option<Items<'py>> {
        let items: Vec<_> = if let Ok(list) = self.0.cast::<PyList>() {
            list.iter().collect()
        } else if let Ok(tuple) = self.0.cast::<PyTuple>() {
            tuple.iter().collect()
        } else {
            return None;
        };
        Some(Items(items.into_iter()))
    }

    /// The entries of a dict, in its order; None for any other value.
    fn entries(&self) -> Option<Entries<'py>> {
        let dict = self.0.cast::<PyDict>().ok()?;
        Some(Entries {
            entries: dict.iter().collect::<Vec<_>>().into_iter(),
            value: None,
        })
    }

    /// Refuses a bool where `expected` wants a number, as the file readers do.
    fn not_bool<'de, V: Visitor<'de>>(&self, expected: &V) -> Result<()> {
        match self.0.cast::<PyBool>() {
            Ok(b) => Err(de::Error::invalid_type(
                Unexpected::Bool(b.is_true()),
                expected,
            )),
            Err(_) => Ok(()),
        }
    }

    /// A list or tuple of exactly `len` elements (a longer one is not cut short silently).
    fn fixed<'de, V: Visitor<'de>>(self, len: usize, visitor: V) -> Result<V::Value> {
        match self.items() {
            Some(items) if items.0.len() != len => {
                Err(de::Error::invalid_length(items.0.len(), &visitor))
            }
            Some(items) => visitor.visit_seq(items),
            None => (&mut Depythonizer::from_object(&self.0)).deserialize_tuple(len, visitor),
        }
    }
}

impl<'de, 'py> Deserializer<'de> for Strict<'py> {
    type Error = PythonizeError;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        if let Some(items) = self.items() {
            return visitor.visit_seq(items);
        }
        if let Some(entries) = self.entries() {
            return visitor.visit_map(entries);
        }
        (&mut Depythonizer::from_object(&self.0)).deserialize_any(visitor)
    }

    number!(
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
    );

    leaf!(
        deserialize_bool,
        deserialize_char,
        deserialize_str,
        deserialize_string,
        deserialize_bytes,
        deserialize_byte_buf,
        deserialize_unit,
        deserialize_identifier,
        deserialize_ignored_any,
    );

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        if self.0.is_none() {
            visitor.visit_none()
        } else {
            visitor.visit_some(self)
        }
    }

    fn deserialize_unit_struct<V: Visitor<'de>>(
        self,
        name: &'static str,
        visitor: V,
    ) -> Result<V::Value> {
        (&mut Depythonizer::from_object(&self.0)).deserialize_unit_struct(name, visitor)
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value> {
        visitor.visit_newtype_struct(self)
    }

    fn deserialize_seq<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        match self.items() {
            Some(items) => visitor.visit_seq(items),
            None => (&mut Depythonizer::from_object(&self.0)).deserialize_seq(visitor),
        }
    }

    fn deserialize_tuple<V: Visitor<'de>>(self, len: usize, visitor: V) -> Result<V::Value> {
        self.fixed(len, visitor)
    }

    fn deserialize_tuple_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        len: usize,
        visitor: V,
    ) -> Result<V::Value> {
        self.fixed(len, visitor)
    }

    fn deserialize_map<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value> {
        match self.entries() {
            Some(entries) => visitor.visit_map(entries),
            None => (&mut Depythonizer::from_object(&self.0)).deserialize_map(visitor),
        }
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value> {
        self.deserialize_map(visitor)
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        name: &'static str,
        variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value> {
        (&mut Depythonizer::from_object(&self.0)).deserialize_enum(name, variants, visitor)
    }
}

/// A list's or tuple's elements, each read strictly.
struct Items<'py>(std::vec::IntoIter<Bound<'py, PyAny>>);

impl<'de, 'py> SeqAccess<'de> for Items<'py> {
    type Error = PythonizeError;

    fn next_element_seed<T: DeserializeSeed<'de>>(&mut self, seed: T) -> Result<Option<T::Value>> {
        self.0
            .next()
            .map(|v| seed.deserialize(Strict(v)))
            .transpose()
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.0.len())
    }
}

/// A dict's entries, keys and values each read strictly.
struct Entries<'py> {
    entries: std::vec::IntoIter<(Bound<'py, PyAny>, Bound<'py, PyAny>)>,
    /// The value of the key just read.
    value: Option<Bound<'py, PyAny>>,
}

impl<'de, 'py> MapAccess<'de> for Entries<'py> {
    type Error = PythonizeError;

    fn next_key_seed<K: DeserializeSeed<'de>>(&mut self, seed: K) -> Result<Option<K::Value>> {
        let Some((key, value)) = self.entries.next() else {
            return Ok(None);
        };
        self.value = Some(value);
        seed.deserialize(Strict(key)).map(Some)
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value> {
        let value = self.value.take().ok_or_else(|| {
            <PythonizeError as de::Error>::custom("a dict's value asked for before its key")
        })?;
        seed.deserialize(Strict(value))
    }

    fn size_hint(&self) -> Option<usize> {
        Some(self.entries.len())
    }
}
