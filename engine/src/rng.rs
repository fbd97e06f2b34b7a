//! A small seeded generator whose sequence is part of the project's results: the rules'
//! random layouts (`Frame::open_table`, and through them the player's benchmarks) and the
//! impact sweeps are defined by it, the same on every machine and every version (unlike
//! `rand`'s `SmallRng`, whose algorithm may change between releases). New code that only needs
//! reproducible randomness uses `rand`'s ChaCha generators, as the planner and the fuzz
//! harness do.

use crate::ball::Vec3;

/// A small deterministic generator of uniform numbers (Marsaglia's xorshift64, 2003): the
/// same sequence on every machine, so that a sweep's impacts are the same everywhere. Seed it
/// with any non-zero value.
#[derive(Clone, Debug)]
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [a, b).
    pub fn uniform(&mut self, a: f64, b: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        a + (b - a) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }

    /// A vector with components uniform in [-a, a).
    pub fn vec(&mut self, a: f64) -> Vec3 {
        Vec3::new(
            self.uniform(-a, a),
            self.uniform(-a, a),
            self.uniform(-a, a),
        )
    }
}
