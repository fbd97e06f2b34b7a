//! The frames benchmark (issue 23): the player against the greedy baseline (the stroke with the
//! highest pot probability, no position play, no safety) over whole frames from the break-off,
//! the break-off alternating (frame k: the player breaks off when k is odd, greedy when k is
//! even), at the standard noise: frames won with a 95 % interval (Wilson's score interval).
//!
//! `cargo bench -p snooker-player --bench frames -- [--frames N] [--from K] [--noise K]
//! [--effort N] [--max-strokes N] [--out FILE.jsonl]`: `--noise` is a multiple of the standard
//! noise. One JSON line per frame goes to FILE (appended as each frame ends), the table to
//! standard output at the end. Frame k is played with seed k. A frame that reaches the stroke
//! cap (stated in the table) is scored to the side ahead on points then, and counted apart.

use snooker_planner::Noise;
use snooker_player::game::{DEFAULT_EFFORT, DEFAULT_MAX_STROKES};
use snooker_player::{Agent, End, Greedy, PlayOptions, Player, Until, play};
use snooker_rules::Frame;
use std::io::Write;
use std::time::Instant;

struct Args {
    frames: u64,
    from: u64,
    noise: f64,
    effort: u64,
    max_strokes: usize,
    out: Option<String>,
}

fn args() -> Args {
    let mut a = Args {
        frames: 50,
        from: 1,
        noise: 1.0,
        effort: DEFAULT_EFFORT,
        max_strokes: DEFAULT_MAX_STROKES,
        out: None,
    };
    let v: Vec<String> = std::env::args().skip(1).collect();
    let mut i = 0;
    while i < v.len() {
        let next = || v.get(i + 1).cloned().unwrap_or_default();
        match v[i].as_str() {
            "--frames" => a.frames = next().parse().expect("--frames N"),
            "--from" => a.from = next().parse().expect("--from K"),
            "--noise" => a.noise = next().parse().expect("--noise K"),
            "--effort" => a.effort = next().parse().expect("--effort N"),
            "--max-strokes" => a.max_strokes = next().parse().expect("--max-strokes N"),
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

/// Wilson's 95 % score interval of `k` successes in `n` trials.
fn wilson(k: u64, n: u64) -> (f64, f64) {
    if n == 0 {
        return (0.0, 1.0);
    }
    let (n, p, z) = (n as f64, k as f64 / n as f64, 1.959_963_984_540_054);
    let centre = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
    let half = z / (1.0 + z * z / n) * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt();
    ((centre - half).max(0.0), (centre + half).min(1.0))
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
    let noise = Noise::STANDARD.scaled(a.noise);
    let (mut won, mut capped, mut n) = (0u64, 0u64, 0u64);
    let (mut pts_player, mut pts_greedy, mut strokes) = (0u64, 0u64, 0usize);
    let mut best = [0u32; 2];
    let start = Instant::now();
    for k in a.from..a.from + a.frames {
        // The player is side `me`; side 0 breaks off.
        let me: u8 = if k % 2 == 1 { 0 } else { 1 };
        let agents: [&dyn Agent; 2] = if me == 0 {
            [&Player, &Greedy]
        } else {
            [&Greedy, &Player]
        };
        let opts = PlayOptions {
            noise,
            seed: k,
            effort: a.effort,
            until: Until::Frame,
            max_strokes: a.max_strokes,
        };
        let game = play(&Frame::break_off(), agents, &opts, |_| {}).expect("a frame");
        let scores = match game.end {
            End::FrameOver { scores, .. } => scores,
            _ => game.last.as_ref().map_or([0, 0], |f| f.state().scores),
        };
        let winner = match game.end {
            End::FrameOver { winner, .. } => Some(winner),
            _ => {
                capped += 1;
                match scores[0].cmp(&scores[1]) {
                    std::cmp::Ordering::Greater => Some(0),
                    std::cmp::Ordering::Less => Some(1),
                    std::cmp::Ordering::Equal => None,
                }
            }
        };
        // Highest break of each agent: consecutive legal pots of one side.
        let (mut run, mut side) = (0u32, u8::MAX);
        for s in &game.strokes {
            if s.player != side {
                run = 0;
                side = s.player;
            }
            if s.verdict.legal() && s.verdict.points > 0 {
                run += s.verdict.points;
                let who = usize::from(s.player != me);
                best[who] = best[who].max(run);
            } else {
                run = 0;
            }
        }
        let player_won = winner == Some(me);
        won += player_won as u64;
        n += 1;
        strokes += game.strokes.len();
        pts_player += u64::from(scores[me as usize]);
        pts_greedy += u64::from(scores[1 - me as usize]);
        if let Some(f) = out.as_mut() {
            let _ = writeln!(
                f,
                "{{\"frame\": {k}, \"noise\": {}, \"effort\": {}, \"player_side\": {me}, \"scores\": [{}, {}], \"player_won\": {player_won}, \"capped\": {}, \"strokes\": {}, \"seconds\": {:.1}}}",
                a.noise,
                a.effort,
                scores[0],
                scores[1],
                !matches!(game.end, End::FrameOver { .. }),
                game.strokes.len(),
                start.elapsed().as_secs_f64()
            );
        }
    }
    let (lo, hi) = wilson(won, n);
    println!(
        "| noise | frames | player won | 95 % interval | mean score (player - greedy) | highest break (player, greedy) | strokes per frame | capped at {} strokes |",
        a.max_strokes
    );
    println!("|---|---|---|---|---|---|---|---|");
    println!(
        "| {} x standard | {n} | {:.0} % ({won}) | {:.0}-{:.0} % | {:.1} - {:.1} | {}, {} | {:.0} | {capped} |",
        a.noise,
        100.0 * won as f64 / n.max(1) as f64,
        100.0 * lo,
        100.0 * hi,
        pts_player as f64 / n.max(1) as f64,
        pts_greedy as f64 / n.max(1) as f64,
        best[0],
        best[1],
        strokes as f64 / n.max(1) as f64,
    );
    eprintln!("{:.0} s", start.elapsed().as_secs_f64());
}
