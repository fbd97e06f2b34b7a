//! The per-shot summaries as a Parquet table (feature `parquet`), which Polars, DuckDB and
//! pandas read directly. One row per scene, in input order; per-ball and per-pot values are
//! list columns of equal length within a row (explode them together to get one row per ball):
//!
//! | column | type | |
//! |---|---|---|
//! | `source`, `scene` | string | where the scene came from, its name |
//! | `error` | string, null for a shot | why the scene failed |
//! | `ending` | string | `at_rest` or `horizon` (null if failed) |
//! | `duration` | f64, s | simulated duration |
//! | `events` | u64 | events resolved |
//! | `pot_ball`, `pot_pocket`, `pot_t` | lists of string, string, f64 (s) | the pots in time order |
//! | `ball`, `x`, `y`, `z`, `motion` | lists of string, f64 (m) x 3, string | every ball at the end |

use crate::Summary;
use arrow_array::builder::{
    ArrayBuilder, Float64Builder, ListBuilder, StringBuilder, UInt64Builder,
};
use arrow_array::{ArrayRef, RecordBatch};
use arrow_schema::{DataType, Field, Schema, SchemaRef};
use std::sync::Arc;

/// A table that could not be encoded.
#[derive(Debug, thiserror::Error)]
pub enum TableError {
    /// The columns did not form a record batch.
    #[error("cannot build the table's columns: {0}")]
    Arrow(#[from] arrow_schema::ArrowError),
    /// The Parquet writer failed.
    #[error("cannot write the Parquet table: {0}")]
    Parquet(#[from] parquet::errors::ParquetError),
}

/// A list column: per row, the values `f` gives, appended by `push`.
fn list<'a, B: ArrayBuilder + Default, T>(
    rows: &'a [Summary],
    f: impl Fn(&'a Summary) -> Vec<T>,
    push: impl Fn(&mut B, T),
) -> ArrayRef {
    let mut b = ListBuilder::new(B::default());
    for r in rows {
        for v in f(r) {
            push(b.values(), v);
        }
        b.append(true);
    }
    Arc::new(b.finish())
}

/// A list-of-strings column.
fn strings<'a>(rows: &'a [Summary], f: impl Fn(&'a Summary) -> Vec<&'a str>) -> ArrayRef {
    list(rows, f, |b: &mut StringBuilder, s| b.append_value(s))
}

/// A list-of-f64 column.
fn floats(rows: &[Summary], f: impl Fn(&Summary) -> Vec<f64>) -> ArrayRef {
    list(rows, f, |b: &mut Float64Builder, v| b.append_value(v))
}

/// A list column's type: lists of `item`, whose values may be null (Arrow's default).
fn list_of(item: DataType) -> DataType {
    DataType::List(Arc::new(Field::new("item", item, true)))
}

/// The table's schema, the same for every batch whatever its rows (so that the tables of
/// several batches concatenate): `error` and the shot's columns are nullable, `source`,
/// `scene` and the lists are not.
pub fn schema() -> SchemaRef {
    use DataType::{Float64, UInt64, Utf8};
    let strings = || list_of(Utf8);
    let floats = || list_of(Float64);
    Arc::new(Schema::new(vec![
        Field::new("source", Utf8, false),
        Field::new("scene", Utf8, false),
        Field::new("error", Utf8, true),
        Field::new("ending", Utf8, true),
        Field::new("duration", Float64, true),
        Field::new("events", UInt64, true),
        Field::new("pot_ball", strings(), false),
        Field::new("pot_pocket", strings(), false),
        Field::new("pot_t", floats(), false),
        Field::new("ball", strings(), false),
        Field::new("x", floats(), false),
        Field::new("y", floats(), false),
        Field::new("z", floats(), false),
        Field::new("motion", strings(), false),
    ]))
}

/// The rows as an Arrow record batch (the columns above, with the schema of [`schema`]).
pub fn record_batch(rows: &[Summary]) -> Result<RecordBatch, TableError> {
    let text = |f: &dyn Fn(&Summary) -> Option<&str>| -> ArrayRef {
        let mut b = StringBuilder::new();
        for r in rows {
            b.append_option(f(r));
        }
        Arc::new(b.finish())
    };
    let mut duration = Float64Builder::new();
    let mut events = UInt64Builder::new();
    for r in rows {
        duration.append_option(r.duration);
        events.append_option(r.events);
    }
    let coord = |k: usize| floats(rows, move |r| r.balls.iter().map(|b| b.1[k]).collect());
    // In the order of [`schema`].
    let columns: Vec<ArrayRef> = vec![
        text(&|r| Some(&r.source)),
        text(&|r| Some(&r.scene)),
        text(&|r| r.error.as_deref()),
        text(&|r| r.ending),
        Arc::new(duration.finish()),
        Arc::new(events.finish()),
        strings(rows, |r| r.pots.iter().map(|p| p.0.as_str()).collect()),
        strings(rows, |r| r.pots.iter().map(|p| p.1.as_str()).collect()),
        floats(rows, |r| r.pots.iter().map(|p| p.2).collect()),
        strings(rows, |r| r.balls.iter().map(|b| b.0.as_str()).collect()),
        coord(0),
        coord(1),
        coord(2),
        strings(rows, |r| r.balls.iter().map(|b| b.2).collect()),
    ];
    Ok(RecordBatch::try_new(schema(), columns)?)
}

/// The rows as the bytes of a Parquet file.
pub fn parquet_bytes(rows: &[Summary]) -> Result<Vec<u8>, TableError> {
    let batch = record_batch(rows)?;
    let mut out = Vec::new();
    let mut writer = parquet::arrow::ArrowWriter::try_new(&mut out, batch.schema(), None)?;
    writer.write(&batch)?;
    writer.close()?;
    Ok(out)
}
