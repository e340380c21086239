//! The arithmetic of half-edges: triangle `t` owns half-edges `3t, 3t+1, 3t+2`, and
//! half-edge `h` runs from `V[h]` to `V[next(h)]`.

pub use crate::NONE;

/// The triangle of half-edge `h`.
#[inline]
pub fn tri(h: u32) -> u32 {
    h / 3
}

/// The next half-edge in the same triangle (counter-clockwise).
#[inline]
pub fn next(h: u32) -> u32 {
    if h % 3 == 2 { h - 2 } else { h + 1 }
}

/// The previous half-edge in the same triangle.
#[inline]
pub fn prev(h: u32) -> u32 {
    if h.is_multiple_of(3) { h + 2 } else { h - 1 }
}

/// The first half-edge of triangle `t`.
#[inline]
pub fn first(t: u32) -> u32 {
    3 * t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn next_and_prev_cycle_inside_a_triangle() {
        for h in 0..30u32 {
            assert_eq!(tri(next(h)), tri(h));
            assert_eq!(prev(next(h)), h);
            assert_eq!(next(next(next(h))), h);
            assert_eq!(next(h), 3 * (h / 3) + (h + 1) % 3);
            assert_eq!(prev(h), 3 * (h / 3) + (h + 2) % 3);
        }
    }
}
