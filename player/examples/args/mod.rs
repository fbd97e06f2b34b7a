//! The diagnostic examples' positional arguments: a value that is given must parse, or the
//! example stops with one message naming the argument and exit status 2; a missing one takes
//! its default.
use std::str::FromStr;

/// Argument `i` (from 0, after the program's name) of `args`, called `name`, or `default`.
pub fn arg<T: FromStr>(args: &[String], i: usize, name: &str, default: T) -> T {
    match args.get(i) {
        None => default,
        Some(s) => s.parse().unwrap_or_else(|_| {
            eprintln!("argument {} ({name}): {s:?} is not a valid {name}", i + 1);
            std::process::exit(2)
        }),
    }
}
