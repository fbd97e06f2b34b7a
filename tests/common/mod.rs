//! Shared helpers of the command line's integration tests.
#![allow(dead_code)]

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs the `snooker` command with `args`.
pub fn snooker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_snooker"))
        .args(args)
        .output()
        .unwrap()
}

/// A fresh, empty temporary directory for test `tag`.
pub fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("snooker-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Everything a recording holds, by entity path (without the leading `/`).
pub fn decode_recording(bytes: &[u8]) -> BTreeMap<String, Vec<rerun::log::Chunk>> {
    use rerun::external::re_log_encoding::DecoderApp;
    use rerun::log::{Chunk, LogMsg};
    let mut out = BTreeMap::<String, Vec<Chunk>>::new();
    for msg in DecoderApp::decode_lazy(bytes) {
        if let LogMsg::ArrowMsg(store, arrow) = msg.expect("a valid .rrd stream")
            && store.kind() == rerun::StoreKind::Recording
        {
            let chunk = Chunk::from_arrow_msg(&arrow).unwrap();
            let path = chunk.entity_path().to_string();
            out.entry(path.trim_start_matches('/').into())
                .or_default()
                .push(chunk);
        }
    }
    out
}

/// A component's rows at an entity: (time in ns, values), in time order (rows at one time in
/// the order logged).
pub fn rows_of<C: rerun::Component + Clone>(
    d: &BTreeMap<String, Vec<rerun::log::Chunk>>,
    entity: &str,
    component: rerun::ComponentIdentifier,
) -> Vec<(i64, Vec<C>)> {
    let timeline = rerun::TimelineName::from(snooker::record::TIMELINE);
    let mut out = Vec::new();
    for chunk in d.get(entity).into_iter().flatten() {
        let Some(times) = chunk.timelines().get(&timeline) else {
            continue;
        };
        let times = times.times_raw().to_vec();
        for ((row, t), v) in chunk
            .row_ids()
            .zip(times)
            .zip(chunk.iter_component::<C>(component))
        {
            out.push((t, row, v.to_vec()));
        }
    }
    out.sort_by_key(|r| (r.0, r.1));
    out.into_iter().map(|(t, _, v)| (t, v)).collect()
}
