//! The open-table benchmark (issue 23): 15 reds scattered at random (non-overlapping, off the
//! cushions), the colours on their spots, the cue ball in hand, one visit, over seeded layouts
//! at several noise levels: mean break, share of total clearances (15 reds and the 6 colours),
//! highest break, pot success per attempted pot, strokes per visit, median decision time.
//!
//! `cargo bench -p snooker-player --bench open_table -- [--layouts N] [--from SEED]
//! [--noise 0,1,2] [--effort N] [--out FILE.jsonl]`: noise levels are multiples of the standard
//! noise. One JSON line per visit goes to FILE (appended as each visit ends, so a long run can
//! be read while it goes), the table to standard output at the end. Layout k is
//! `layouts::open_table_in_hand(k)`, played with seed k.

use snooker_planner::Noise;
use snooker_player::game::DEFAULT_EFFORT;
use snooker_player::{End, PlanKind, PlayOptions, Player, play};
use std::io::Write;
use std::time::Instant;

struct Args {
    layouts: u64,
    from: u64,
    noise: Vec<f64>,
    effort: u64,
    out: Option<String>,
}

fn args() -> Args {
    let mut a = Args {
        layouts: 100,
        from: 1,
        noise: vec![0.0, 1.0, 2.0],
        effort: DEFAULT_EFFORT,
        out: None,
    };
    let v: Vec<String> = std::env::args().skip(1).collect();
    let mut i = 0;
    while i < v.len() {
        let next = || v.get(i + 1).cloned().unwrap_or_default();
        match v[i].as_str() {
            "--layouts" => a.layouts = next().parse().expect("--layouts N"),
            "--from" => a.from = next().parse().expect("--from SEED"),
            "--effort" => a.effort = next().parse().expect("--effort N"),
            "--noise" => {
                a.noise = next()
                    .split(',')
                    .map(|s| s.parse().expect("--noise K,K,..."))
                    .collect()
            }
            "--out" => a.out = Some(next()),
            // cargo bench passes --bench.
            _ => {
                i += 1;
                continue;
            }
        }
        i += 2;
    }
    a
}

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn main() {
    let a = args();
    let mut out = a.out.as_ref().map(|p| {
        std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(p)
            .expect("--out file")
    });
    println!(
        "| noise | layouts | mean break | clearances | highest | pots / attempts | strokes per visit | median decision | mean decision |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for &k in &a.noise {
        let noise = Noise::STANDARD.scaled(k);
        let (mut breaks, mut clear, mut strokes) = (Vec::new(), 0, 0usize);
        let (mut attempts, mut made) = (0usize, 0usize);
        let mut times = Vec::new();
        let start = Instant::now();
        for seed in a.from..a.from + a.layouts {
            let frame = snooker_player::layouts::open_table_in_hand(seed);
            let opts = PlayOptions {
                noise,
                seed,
                effort: a.effort,
                ..PlayOptions::default()
            };
            let game = play(&frame, [&Player, &Player], &opts, |_| {}).expect("a visit");
            let points = game.points(0);
            let cleared = matches!(game.end, End::FrameOver { .. })
                && game.last.is_none()
                && game.strokes.iter().all(|s| s.verdict.legal());
            let (mut att, mut pot) = (0, 0);
            for s in &game.strokes {
                times.push(s.decision_time);
                if s.decision.plan.kind != PlanKind::Safety {
                    att += 1;
                    if s.verdict.legal() && s.verdict.potted.contains(&s.decision.plan.pot) {
                        pot += 1;
                    }
                }
            }
            attempts += att;
            made += pot;
            strokes += game.strokes.len();
            clear += cleared as usize;
            breaks.push(points);
            if let Some(f) = out.as_mut() {
                let t: Vec<f64> = game.strokes.iter().map(|s| s.decision_time).collect();
                let _ = writeln!(
                    f,
                    "{{\"noise\": {k}, \"seed\": {seed}, \"effort\": {}, \"break\": {points}, \"cleared\": {cleared}, \"strokes\": {}, \"attempts\": {att}, \"pots\": {pot}, \"decision_times\": {:?}}}",
                    a.effort,
                    game.strokes.len(),
                    t
                );
            }
        }
        let n = breaks.len() as f64;
        println!(
            "| {k} x standard | {} | {:.1} | {:.0} % ({clear}) | {} | {:.1} % ({made}/{attempts}) | {:.1} | {:.2} s | {:.2} s |",
            breaks.len(),
            breaks.iter().sum::<u32>() as f64 / n,
            100.0 * clear as f64 / n,
            breaks.iter().max().unwrap_or(&0),
            100.0 * made as f64 / attempts.max(1) as f64,
            strokes as f64 / n,
            median(times.clone()),
            times.iter().sum::<f64>() / times.len().max(1) as f64,
        );
        eprintln!("noise {k}: {:.0} s", start.elapsed().as_secs_f64());
    }
}
