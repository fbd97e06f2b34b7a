//! `fuzz`: random and hostile scenes through the scene parser and the engine on every core,
//! every invariant checked ([`check`]); every failing scene is written to a file with why.
//!
//! `cargo run --release -p snooker-fuzz -- --scenes 10000 [--seed S] [--out failures.toml]`
//! (a fresh seed, printed, when none is given). `--only K --seed S` reruns scene K alone and
//! prints its scene file; `--from K` starts at scene K (a long run in parts). The printed digest
//! hashes every result: a change meant to leave every bit alone must leave it alone.

mod check;
mod generate;

use clap::Parser;
use generate::{Kind, generate};
use indicatif::{ProgressBar, ProgressStyle};
use rand::SeedableRng;
use rand::rngs::ChaCha8Rng;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    about = "Random and hostile scenes through the parser and the engine, invariants checked"
)]
struct Args {
    /// Number of scenes.
    #[arg(long, default_value_t = 10_000)]
    scenes: u64,
    /// Seed (default: a fresh one from the clock, printed).
    #[arg(long)]
    seed: Option<u64>,
    /// File the failing scenes are written to.
    #[arg(long, default_value = "fuzz-failures.toml")]
    out: PathBuf,
    /// Index of the first scene: `--from K --scenes N` runs scenes K..K+N of the seed, so a
    /// long run can be done in parts (each scene has its own generator).
    #[arg(long, default_value_t = 0, value_name = "K")]
    from: u64,
    /// Run scene K alone and print its file.
    #[arg(long, value_name = "K")]
    only: Option<u64>,
    /// Also write each scene's digest to this file, one `K DIGEST` line per scene: two runs'
    /// files show which scenes a change touched.
    #[arg(long, value_name = "FILE")]
    digests: Option<PathBuf>,
}

/// Scene `k` of run `seed`: its own generator, so any scene can be rerun alone.
fn scene(seed: u64, k: u64) -> generate::Generated {
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ k.wrapping_mul(0x9e37_79b9_7f4a_7c15));
    let kind = Kind::of_scene(k);
    generate(kind, &mut rng)
}

fn main() -> ExitCode {
    let args = Args::parse();
    let seed = args.seed.unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(1, |d| d.as_nanos() as u64)
    });
    // Panics are caught and reported per scene.
    std::panic::set_hook(Box::new(|_| {}));
    if let Some(k) = args.only {
        let g = scene(seed, k);
        print!("{}", g.text);
        let v = check::check(&g);
        eprintln!(
            "scene {k} ({}): {}{}",
            g.kind.name(),
            v.ending.name(),
            v.failure.map_or(String::new(), |f| format!("; FAILS: {f}"))
        );
        return ExitCode::SUCCESS;
    }
    let (first, end) = (args.from, args.from.saturating_add(args.scenes));
    eprintln!("fuzz: scenes {first}..{end} of seed {seed}");
    let bar = ProgressBar::new(end - first);
    if let Ok(style) = ProgressStyle::with_template(
        "{elapsed_precise} [{bar:40}] {pos}/{len} scenes ({per_sec}) {msg}",
    ) {
        bar.set_style(style.progress_chars("=> "));
    }
    // A scene's text is kept only if it fails: a run of 10^6 scenes must fit in memory.
    let results: Vec<(u64, Kind, check::SceneCheck, f64, Option<String>)> = (first..end)
        .into_par_iter()
        .map(|k| {
            let g = scene(seed, k);
            let start = std::time::Instant::now();
            let v = check::check(&g);
            let took = start.elapsed().as_secs_f64();
            if took > 10.0 {
                bar.println(format!("scene {k} ({}) took {took:.0} s", g.kind.name()));
            }
            bar.inc(1);
            let text = v.failure.is_some().then_some(g.text);
            (k, g.kind, v, took, text)
        })
        .collect();
    bar.finish_and_clear();
    let mut table: BTreeMap<(Kind, check::SceneEnding, bool), u64> = BTreeMap::new();
    let mut failures = String::new();
    let mut failed = 0;
    for (k, kind, v, _, text) in &results {
        *table.entry((*kind, v.ending, v.physical)).or_default() += 1;
        if let (Some(f), Some(text)) = (&v.failure, text) {
            failed += 1;
            let _ = writeln!(
                failures,
                "# ---- scene {k} of seed {seed} ({}): {f}\n# rerun: cargo run --release -p snooker-fuzz -- --seed {seed} --only {k}\n{}",
                kind.name(),
                text
            );
        }
    }
    let mut slowest: Vec<(f64, u64, &str)> = results
        .iter()
        .map(|(k, kind, _, t, _)| (*t, *k, kind.name()))
        .collect();
    slowest.sort_by(|a, b| b.0.total_cmp(&a.0));
    let total: f64 = results.iter().map(|r| r.3).sum();
    println!(
        "seed {seed}: scenes {first}..{end} ({} scenes), {failed} failing",
        end - first
    );
    // One hash of every result in scene order: equal before and after a change that should
    // leave every bit of every shot alone.
    let digest = results
        .iter()
        .fold(0u64, |h, r| h.rotate_left(5) ^ r.2.digest);
    println!("digest of the results: {digest:016x}");
    if let Some(path) = &args.digests {
        let lines: String = results
            .iter()
            .map(|r| format!("{} {:016x}\n", r.0, r.2.digest))
            .collect();
        if let Err(e) = std::fs::write(path, lines) {
            eprintln!("error: cannot write {}: {e}", path.display());
        }
    }
    println!(
        "time in scenes {total:.1} s (mean {:.2} ms); slowest: {}",
        1e3 * total / (end - first).max(1) as f64,
        slowest
            .iter()
            .take(5)
            .map(|(t, k, kind)| format!("{k} ({kind}) {t:.2} s"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    println!(
        "{:<16} {:<26} {:>9} {:>9}",
        "kind", "ending", "physical", "other"
    );
    for kind in Kind::ALL {
        let times: Vec<f64> = results
            .iter()
            .filter(|r| r.1 == kind)
            .map(|r| r.3)
            .collect();
        let mean_ms = 1e3 * times.iter().sum::<f64>() / times.len().max(1) as f64;
        println!(
            "{} ({} scenes, mean {mean_ms:.2} ms)",
            kind.name(),
            times.len()
        );
        let endings: Vec<check::SceneEnding> = {
            let mut e: Vec<_> = table
                .keys()
                .filter(|(k, _, _)| *k == kind)
                .map(|(_, e, _)| *e)
                .collect();
            e.dedup();
            e
        };
        for e in endings {
            let n = |phys| table.get(&(kind, e, phys)).copied().unwrap_or(0);
            println!(
                "{:<16} {:<26} {:>9} {:>9}",
                kind.name(),
                e.name(),
                n(true),
                n(false)
            );
        }
    }
    // Coverage: how many scenes of each kind reached each event kind and class.
    let mut coverage: BTreeMap<Kind, (u64, [u64; check::FEATURES.len()])> = BTreeMap::new();
    for (_, kind, v, _, _) in &results {
        let row = coverage
            .entry(*kind)
            .or_insert((0, [0; check::FEATURES.len()]));
        row.0 += 1;
        for (k, n) in row.1.iter_mut().enumerate() {
            *n += u64::from(v.reached >> k & 1);
        }
    }
    println!("coverage: scenes of each kind that reached each event kind and class");
    let mut header = format!("{:<16} {:>7}", "kind", "scenes");
    for f in check::FEATURES {
        let _ = write!(header, " {f:>w$}", w = f.len().max(6));
    }
    println!("{header}");
    for kind in Kind::ALL {
        let Some((n, counts)) = coverage.get(&kind) else {
            continue;
        };
        let mut line = format!("{:<16} {n:>7}", kind.name());
        for (f, c) in check::FEATURES.iter().zip(counts) {
            let _ = write!(line, " {c:>w$}", w = f.len().max(6));
        }
        println!("{line}");
    }
    // Why the cloth was not a physical one, for the shots that did not stop.
    let mut why: BTreeMap<(check::SceneEnding, &str), u64> = BTreeMap::new();
    for (_, _, v, _, _) in &results {
        if let Some(reason) = v.unphysical
            && matches!(
                v.ending,
                check::SceneEnding::DidNotStop | check::SceneEnding::EventCap
            )
        {
            *why.entry((v.ending, reason)).or_default() += 1;
        }
    }
    if !why.is_empty() {
        println!("near-frictionless cloths among the shots that did not finish:");
        for ((ending, reason), n) in &why {
            println!("  {:<26} {reason:<36} {n:>6}", ending.name());
        }
    }
    if failed > 0 {
        if let Err(e) = std::fs::write(&args.out, &failures) {
            eprintln!("error: cannot write {}: {e}", args.out.display());
        } else {
            println!("failing scenes written to {}", args.out.display());
        }
        return ExitCode::from(1);
    }
    ExitCode::SUCCESS
}
