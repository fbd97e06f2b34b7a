//! The Parquet table read back (by the parquet crate's own Arrow reader): one row per scene in
//! input order, the columns the docs name, a failed scene with its error and null results.

use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use snooker_batch::input::from_json_lines;
use snooker_batch::table::parquet_bytes;
use snooker_batch::{Summary, run_sources};

#[test]
fn the_table_reads_back() {
    let good = r#"{"balls": [{"id": "cue", "pos": [1.0, 0.8]}, {"id": "red", "pos": [3.45, 1.66]}], "cue": {"ball": "cue", "speed": 4.0, "aim": 0.36}}"#;
    let text = format!("{good}\n{{\"balls\": []}}\n");
    let sources = from_json_lines(&text, "t.jsonl");
    let outcomes = run_sources(&sources, Some(2), || {}).unwrap();
    let rows: Vec<Summary> = sources
        .iter()
        .zip(&outcomes)
        .map(|(s, o)| Summary::of_outcome(&s.name, o))
        .collect();
    let bytes = bytes::Bytes::from(parquet_bytes(&rows).unwrap());
    let reader = ParquetRecordBatchReaderBuilder::try_new(bytes)
        .unwrap()
        .build()
        .unwrap();
    let batches: Vec<_> = reader.map(Result::unwrap).collect();
    let batch = &batches[0];
    assert_eq!(batch.num_rows(), 2);
    let names: Vec<_> = batch
        .schema()
        .fields()
        .iter()
        .map(|f| f.name().clone())
        .collect();
    assert_eq!(
        names,
        [
            "source",
            "scene",
            "error",
            "ending",
            "duration",
            "events",
            "pot_ball",
            "pot_pocket",
            "pot_t",
            "ball",
            "x",
            "y",
            "z",
            "motion"
        ]
    );
    use arrow_array::cast::AsArray;
    use arrow_array::types::{Float64Type, UInt64Type};
    let col = |n: &str| batch.column_by_name(n).unwrap().clone();
    let sources = col("source");
    assert_eq!(sources.as_string::<i32>().value(1), "t.jsonl:2");
    let error = col("error");
    assert!(error.is_null(0));
    assert!(error.as_string::<i32>().value(1).contains("no balls"));
    let shot = outcomes[0].shot.as_ref().unwrap().as_ref().unwrap();
    assert_eq!(
        col("duration")
            .as_primitive::<Float64Type>()
            .value(0)
            .to_bits(),
        shot.duration.to_bits()
    );
    assert!(col("duration").is_null(1));
    assert_eq!(
        col("events").as_primitive::<UInt64Type>().value(0),
        shot.events.len() as u64
    );
    let x = col("x");
    let xs = x.as_list::<i32>().value(0);
    let finals = shot.final_states();
    for (i, s) in finals.iter().enumerate() {
        assert_eq!(
            xs.as_primitive::<Float64Type>().value(i).to_bits(),
            s.pos.x.to_bits()
        );
    }
    assert_eq!(x.as_list::<i32>().value(1).len(), 0);
    let balls = col("ball");
    let ids = balls.as_list::<i32>().value(0);
    assert_eq!(ids.as_string::<i32>().value(1), "red");
}

/// The schema a reader sees in the Parquet table of `rows`.
fn schema_of(rows: &[Summary]) -> arrow_schema::SchemaRef {
    let bytes = bytes::Bytes::from(parquet_bytes(rows).unwrap());
    ParquetRecordBatchReaderBuilder::try_new(bytes)
        .unwrap()
        .schema()
        .clone()
}

/// The rows of the JSON-lines scenes `text`.
fn rows_of(text: &str) -> Vec<Summary> {
    let sources = from_json_lines(text, "t.jsonl");
    let outcomes = run_sources(&sources, Some(1), || {}).unwrap();
    let rows = sources.iter().zip(&outcomes);
    rows.map(|(s, o)| Summary::of_outcome(&s.name, o)).collect()
}

/// The tables of two batches concatenate (pyarrow's `concat_tables`, Polars' `concat`, a
/// DuckDB glob over both): their schemas are the same whether a scene failed or none did.
/// Inferred from the data, `ending`, `duration` and `events` were non-nullable in a batch
/// without failures and nullable in one with a failure, and the two tables did not concatenate.
#[test]
fn the_schema_does_not_depend_on_the_rows() {
    let good = r#"{"balls": [{"id": "cue", "pos": [1.0, 0.8]}, {"id": "red", "pos": [2.0, 0.9]}], "cue": {"ball": "cue", "speed": 2.0, "aim": 0.1}}"#;
    let shots = schema_of(&rows_of(&format!("{good}\n")));
    let with_failure = schema_of(&rows_of(&format!("{good}\n{{\"balls\": []}}\n")));
    assert_eq!(shots, with_failure);
    assert_eq!(shots, snooker_batch::table::schema());
    for nullable in ["error", "ending", "duration", "events"] {
        assert!(
            shots.field_with_name(nullable).unwrap().is_nullable(),
            "{nullable}"
        );
    }
}
