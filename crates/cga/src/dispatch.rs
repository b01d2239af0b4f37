//! Runtime CPU dispatch for the hot kernels.
//!
//! The baseline x86-64 target has only SSE2, and the compiler does not vectorise the
//! blocked product well by itself, so an AVX build of the same computation is chosen at
//! run time where the CPU has AVX. Both sum the same products in the same order without
//! fused multiply-adds, so results do not depend on the CPU.

use crate::generated;

/// Dense geometric product, with the AVX kernel where the CPU has it.
#[inline]
pub(crate) fn geometric(a: &[f64; 32], b: &[f64; 32]) -> [f64; 32] {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx") {
            // SAFETY: the CPU supports AVX, checked just above.
            return unsafe { generated::geometric_avx(a, b) };
        }
    }
    generated::geometric(a, b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dispatched_kernel_is_bit_identical_to_baseline() {
        for seed in 0..50 {
            let a: [f64; 32] = std::array::from_fn(|i| ((seed * 32 + i) as f64 * 0.37).sin() * 1e3);
            let b: [f64; 32] = std::array::from_fn(|i| ((seed * 32 + i) as f64 * 0.91).cos());
            assert_eq!(geometric(&a, &b), generated::geometric(&a, &b));
        }
    }
}
