//! The command line's small languages, shared by its commands: `--param NAME=VALUE`. The
//! libraries take typed values; only the command line reads these strings and names its flags
//! in messages.

use snooker_engine::Params;
use snooker_scene::OverrideError;

/// `NAME=VALUE` overrides as (name, value) pairs; a malformed one, or a name given twice (a
/// typo: the last value was kept silently), is a message naming it.
pub fn param_pairs(given: &[String]) -> Result<Vec<(String, f64)>, String> {
    let mut pairs: Vec<(String, f64)> = Vec::new();
    for o in given {
        let (name, value) = o
            .split_once('=')
            .ok_or_else(|| format!("--param {o}: expected NAME=VALUE"))?;
        let v: f64 = value
            .trim()
            .parse()
            .map_err(|_| format!("--param {o}: {value} is not a number"))?;
        let name = name.trim().to_string();
        if pairs.iter().any(|(n, _)| *n == name) {
            return Err(format!("--param {o}: `{name}` is given twice"));
        }
        pairs.push((name, v));
    }
    Ok(pairs)
}

/// An override error as the command says it, naming the `--param` given.
pub fn param_error(given: &[String], e: &OverrideError) -> String {
    let shown = given
        .iter()
        .find(|o| o.split_once('=').map(|(n, _)| n.trim()) == Some(e.name()))
        .map_or(e.name(), String::as_str);
    match e {
        OverrideError::Unknown { .. } => format!("--param {shown}: {e}"),
        OverrideError::Invalid(_) => format!("--param {e}"),
    }
}

/// `base` with the `--param NAME=VALUE` overrides applied and checked.
pub fn params(base: Params, given: &[String]) -> Result<Params, String> {
    snooker_scene::override_params(base, &param_pairs(given)?).map_err(|e| param_error(given, &e))
}

/// `base` changed by the noise spec `spec` of flag `flag`: comma-separated items applied in
/// order, each `standard` (the tournaments' noise), `standard*K` (it times K), `0` (none) or
/// `NAME=VALUE` (one standard deviation: aim and elevation in rad, speed in m/s, side and
/// height in m). The old planner spelling `offset=M` (one value for both tip offsets) is
/// still taken as `side=M,height=M`; but beside `speed` it is refused, since the old spelling's
/// `speed` was a fraction of the cue speed and would now be read in m/s.
pub fn noise(
    flag: &str,
    spec: &str,
    base: snooker_planner::Noise,
) -> Result<snooker_planner::Noise, String> {
    use snooker_planner::{Noise, NoiseComponent};
    let mut noise = base;
    let names: Vec<&str> = spec
        .split(',')
        .filter_map(|p| p.split_once('=').map(|(n, _)| n.trim()))
        .collect();
    if names.contains(&"offset") && names.contains(&"speed") {
        return Err(format!(
            "{flag} {spec}: the old spelling (speed as a fraction of the cue speed, one offset) \
             is no longer read: speed is now in m/s (the old speed=F at cue speed V is \
             speed=F*V) and offset is side=M,height=M"
        ));
    }
    // A name given twice kept the last value silently (`aim=0.1,aim=0.2`): a typo, refused.
    let expanded: Vec<&str> = names
        .iter()
        .flat_map(|&n| match n {
            "offset" => vec!["side", "height"],
            n => vec![n],
        })
        .collect();
    if let Some(twice) = (0..expanded.len()).find(|&k| expanded[..k].contains(&expanded[k])) {
        return Err(format!(
            "{flag} {spec}: `{}` is given twice",
            expanded[twice]
        ));
    }
    for part in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        if part == "standard" {
            noise = Noise::STANDARD;
            continue;
        }
        if part == "0" || part == "none" {
            noise = Noise::ZERO;
            continue;
        }
        if let Some(k) = part.strip_prefix("standard*") {
            let k = k
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|k| k.is_finite() && *k >= 0.0)
                .ok_or_else(|| format!("{flag} {part}: expected standard*K with K >= 0"))?;
            noise = Noise::STANDARD.scaled(k);
            continue;
        }
        let (name, value) = part.split_once('=').ok_or_else(|| {
            format!("{flag} {part}: expected standard, standard*K, 0 or NAME=VALUE")
        })?;
        let v = value
            .trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| format!("{flag} {part}: expected a finite number >= 0"))?;
        let name = name.trim();
        if name == "offset" {
            noise.side = v;
            noise.height = v;
            continue;
        }
        let c = NoiseComponent::from_name(name).ok_or_else(|| {
            format!(
                "{flag} {part}: unknown noise `{name}` (aim, elevation, speed, side, height; \
                 or offset for both side and height)"
            )
        })?;
        noise.set(c, v);
    }
    Ok(noise)
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_planner::Noise;

    /// A parameter named twice is refused (impact kept the last of `e_ball=0`, `e_ball=1`).
    #[test]
    fn a_param_given_twice_is_refused() {
        let given = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let e = param_pairs(&given(&["e_ball=0", " e_ball = 1"])).unwrap_err();
        assert!(e.contains("`e_ball` is given twice"), "{e}");
        let ok = param_pairs(&given(&["e_ball=0.9", "mu_ball=0.1"])).unwrap();
        assert_eq!(
            ok,
            [("e_ball".to_string(), 0.9), ("mu_ball".to_string(), 0.1)]
        );
    }

    #[test]
    fn noise_specs() {
        let s = Noise::STANDARD;
        assert_eq!(noise("--noise", "", s), Ok(s));
        assert_eq!(noise("--noise", "0", s), Ok(Noise::ZERO));
        assert_eq!(noise("--noise", "standard", Noise::ZERO), Ok(s));
        assert_eq!(
            noise("--noise", "standard*2", Noise::ZERO),
            Ok(s.scaled(2.0))
        );
        let n = noise("--noise", "0,aim=0.002,offset=0.001", s).unwrap();
        assert_eq!(
            (n.aim, n.speed, n.side, n.height),
            (0.002, 0.0, 0.001, 0.001)
        );
        let n = noise("--noise", "speed=0.1", s).unwrap();
        assert_eq!((n.aim, n.speed), (s.aim, 0.1));
        for bad in ["aim=-1", "aim=x", "blur=1", "standard*x", "loud"] {
            let e = noise("--noise", bad, s).unwrap_err();
            assert!(e.starts_with("--noise "), "{e}");
        }
        let e = noise("--noise", "aim=0.002,speed=0.02,offset=0.001", s).unwrap_err();
        assert!(e.contains("m/s"), "{e}");
        // A name twice (offset is side and height) was played with its last value.
        for twice in ["aim=0.1,aim=0.2", "0,side=0.001,offset=0.002"] {
            let e = noise("--noise", twice, s).unwrap_err();
            assert!(e.contains("given twice"), "{e}");
        }
    }
}
