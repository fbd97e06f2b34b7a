//! Convergence of the impact solvers over random impacts (`snooker_engine::impact::sweep`): for each, the
//! largest difference (fraction of the speed V; spins as R w / V) between the velocities after
//! the impact at the default tolerance (or those given) and a converged solution, for the
//! ball-ball or the cushion model. Prints the distribution, and the five worst impacts with
//! the converged solution's own sensitivity (its change, per 1e-9, when the approach speed
//! changes by one part in 1e9: an error far above that is the solver's, not the problem's).
//! `compliant` runs the cushion impacts against the compliant cushion (default backing; the
//! impacts faster than its travel, 1.853 m/s, meet the backing).
//!
//! `cargo run --release -p snooker-engine --example impact_sweep -- bb|cushion|compliant N [TOL...]`
use snooker_engine::Params;
use snooker_engine::impact::impulse::TOLERANCE;
use snooker_engine::impact::sweep::{self, CONVERGED, Rng, convergence, difference, random_impact};
use std::io::Write;

fn main() -> std::io::Result<()> {
    let usage = || -> ! {
        eprintln!(
            "usage: impact_sweep bb|cushion|compliant [N (default 20000)] [TOL...] (TOL > 0)"
        );
        std::process::exit(2);
    };
    let mut args = std::env::args().skip(1);
    let (cushion, compliant) = match args.next().as_deref() {
        Some("bb") => (false, false),
        Some("cushion") => (true, false),
        Some("compliant") => (true, true),
        _ => usage(),
    };
    let n: usize = match args.next() {
        None => 20_000,
        Some(s) => match s.parse() {
            Ok(n) if n > 0 => n,
            _ => {
                eprintln!("impact_sweep: N must be a positive whole number, not {s:?}");
                usage()
            }
        },
    };
    let mut tols = Vec::new();
    for s in args {
        match s.parse::<f64>() {
            Ok(t) if t > 0.0 && t.is_finite() => tols.push(t),
            _ => {
                eprintln!("impact_sweep: a tolerance must be a positive number, not {s:?}");
                usage()
            }
        }
    }
    if tols.is_empty() {
        tols.push(TOLERANCE);
    }
    let p = Params::default();
    let (r, mass) = (p.ball_radius, p.ball_mass);
    let mut rng = Rng(sweep::SEED);
    let impacts: Vec<_> = (0..n)
        .map(|_| {
            let mut i = random_impact(&mut rng, cushion);
            if compliant {
                i.contact.backing = Some(p.cushion_backing());
            }
            i
        })
        .collect();
    let mut out = std::io::stdout().lock();
    for tol in tols {
        let mut errors: Vec<(f64, usize)> = Vec::with_capacity(n);
        let mut steps = 0;
        for (i, impact) in impacts.iter().enumerate() {
            let (err, s) = convergence(impact, tol);
            errors.push((err, i));
            steps += s;
            if (i + 1) % (n / 100).max(1) == 0 {
                eprint!("\rtolerance {tol:e}: {} of {n} impacts", i + 1);
            }
        }
        eprintln!();
        errors.sort_by(|a, b| a.0.total_cmp(&b.0));
        writeln!(
            out,
            "tolerance {tol:e}: mean steps {:.1}; error (fraction of V) median {:.2e}, 99th percentile {:.2e}, worst {:.2e}",
            steps as f64 / n as f64,
            errors[n / 2].0,
            errors[n * 99 / 100].0,
            errors[n - 1].0
        )?;
        for &(err, i) in errors.iter().rev().take(5) {
            let impact = &impacts[i];
            let c = &impact.contact;
            let fine = c.solve_to(&impact.kin, r, mass, CONVERGED, None).unwrap();
            let mut nudged = impact.kin;
            nudged.vel[0] *= 1.0 + 1e-9;
            let moved = c.solve_to(&nudged, r, mass, CONVERGED, None).unwrap();
            let gain = difference(&moved.after, &fine.after, impact.speed, r) / 1e-9;
            writeln!(out, "  {err:.2e}  {}; sensitivity {gain:.1}", impact.text)?;
        }
    }
    Ok(())
}
