//! Writes the benchmarks' open table of a seed as a frame file (15 reds scattered, the colours
//! on their spots, the cue ball in hand): `cargo run -p snooker-player --example open_table --
//! SEED > frame.toml`.
fn main() {
    let seed: u64 = std::env::args()
        .nth(1)
        .map_or(1, |s| s.parse().expect("a seed"));
    print!(
        "{}",
        snooker_player::layouts::open_table_in_hand(seed).to_toml(None)
    );
}
