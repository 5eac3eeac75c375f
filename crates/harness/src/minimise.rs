//! Minimising a counterexample: fewer vertices and shorter numbers, same class.

use super::classify::{compare_as, Class, Hunted};
use crate::case::RawCase;

/// How many comparisons one minimisation may spend (each runs the exact oracle).
pub const BUDGET: usize = 300;

/// `x` rounded to `digits` significant decimal digits (the shortest f64 that prints so).
fn round_sig(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let s = format!("{:.*e}", (digits - 1).max(0) as usize, x);
    s.parse().unwrap_or(x)
}

/// Every number of the case, by position, for rewriting one at a time.
fn numbers(raw: &mut RawCase) -> Vec<&mut f64> {
    let mut v: Vec<&mut f64> = vec![&mut raw.lookahead];
    v.extend(raw.pos.iter_mut());
    v.extend(raw.vel.iter_mut());
    for p in raw.vertices.iter_mut() {
        v.extend(p.iter_mut());
    }
    for p in raw.velocities.iter_mut() {
        v.extend(p.iter_mut());
    }
    if let Some(s) = raw.slab.as_mut() {
        v.extend(s.iter_mut());
    }
    v
}

/// A smaller case of the same class for the `hunted` engine (greedy; at most [`BUDGET`]
/// comparisons).
pub fn minimise(raw: &RawCase, class: Class, hunted: Hunted) -> RawCase {
    let mut best = raw.clone();
    let mut budget = BUDGET;
    let keeps = |c: &RawCase, budget: &mut usize| -> bool {
        if *budget == 0 {
            return false;
        }
        *budget -= 1;
        matches!(compare_as(c, hunted), Ok(v) if v.class == class)
    };
    // Fewer vertices.
    let mut k = 0;
    while best.vertices.len() > 3 && k < best.vertices.len() {
        let mut c = best.clone();
        c.vertices.remove(k);
        c.velocities.remove(k);
        if keeps(&c, &mut budget) {
            best = c;
        } else {
            k += 1;
        }
    }
    // Shorter numbers: the fewest significant digits (1…6) that keep the class.
    let count = numbers(&mut best.clone()).len();
    for idx in 0..count {
        for digits in 1..=6 {
            let mut c = best.clone();
            let mut nums = numbers(&mut c);
            let x = *nums[idx];
            let r = round_sig(x, digits);
            if r == x {
                break;
            }
            *nums[idx] = r;
            if keeps(&c, &mut budget) {
                best = c;
                break;
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_keeps_digits() {
        assert_eq!(round_sig(123.456, 2), 120.0);
        assert_eq!(round_sig(-0.0012345, 3), -0.00123);
        assert_eq!(round_sig(0.0, 3), 0.0);
    }

    #[test]
    fn minimised_case_keeps_its_class_and_shrinks() {
        // An octagon the point clearly enters: minimising "agree" drops vertices and digits.
        let verts: Vec<[f64; 2]> = (0..8)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 8.0;
                [10.0 * a.cos() + 0.123_456_789, 10.0 * a.sin()]
            })
            .collect();
        let raw = RawCase {
            lookahead: 10.0,
            buff: 0.01,
            fac: 1e-4,
            pos: vec![-30.0, 0.3],
            vel: vec![5.0, 0.0],
            vertices: verts,
            velocities: vec![[0.0, 0.0]; 8],
            slab: None,
        };
        let small = minimise(&raw, Class::Agree, Hunted::Certified);
        assert!(small.vertices.len() < 8);
        assert_eq!(
            compare_as(&small, Hunted::Certified).map(|v| v.class),
            Ok(Class::Agree)
        );
    }
}
