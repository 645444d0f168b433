//! The run-time choice of lanes: [`run_widest`] picks the widest backend the processor has.
//! It sits above the backends (it names them); they import only the common types of `real.rs`.

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
use super::portable::Lanes;
use super::real::LanesOp;

/// Runs `op` on the widest lanes the processor has: eight (`avx512::Avx8`) where x86-64 has
/// AVX-512, four (`avx::Avx4`) where it has AVX2 (checked at run time; `pulp` compiles the code
/// for them and keeps the `unsafe` of calling it on its side), four in two wasm SIMD registers
/// (`wasm::Wasm4`) on wasm32 built with `simd128`, two (`Lanes<2>`: SSE2, NEON) everywhere
/// else. Every kind of lane computes the same IEEE operations in the same order (no fused multiply-add is
/// formed), so the results do not depend on the processor.
#[cfg(lanes)]
#[inline(always)]
pub(crate) fn run_widest<Op: LanesOp>(op: Op) -> Op::Output {
    #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
    {
        if max_width() >= 4 {
            op.run(super::wasm::Wasm4::zero())
        } else {
            op.run(super::wasm::Wasm2::zero())
        }
    }
    #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
    {
        #[cfg(target_arch = "x86_64")]
        {
            let max = max_width();
            if max >= 8 {
                if let Some(avx512) = super::avx512::Avx8::detect() {
                    return avx512.vectorize(op);
                }
            }
            if max >= 4 {
                if let Some(avx) = super::avx::Avx4::detect() {
                    return avx.vectorize(op);
                }
            }
        }
        op.run(Lanes([0.0; 2]))
    }
}

/// The widest lanes the batches may use: all of them, except inside tests' `with_max_width`, so
/// that the narrower routes are covered on machines with wider ones, and in a build with the
/// feature `lane-cap`, where `SCREWBENDER_MAX_LANES` says (see [`lane_cap`]). Only where there is
/// a choice of width (x86-64, wasm32 with SIMD); elsewhere the two lanes are the only ones.
#[cfg(all(
    lanes,
    any(
        target_arch = "x86_64",
        all(target_arch = "wasm32", target_feature = "simd128")
    )
))]
#[inline(always)]
fn max_width() -> usize {
    #[cfg(test)]
    return tests::max_width();
    #[cfg(all(not(test), feature = "lane-cap"))]
    return lane_cap();
    #[cfg(not(any(test, feature = "lane-cap")))]
    usize::MAX
}

/// The cap that `SCREWBENDER_MAX_LANES` sets (`8`, `4` or `2`; unset or empty: none), read once. A
/// measuring build's switch, so a value it cannot honour stops the program with a message
/// rather than measuring something else than asked.
#[cfg(all(
    lanes,
    not(test),
    feature = "lane-cap",
    any(
        target_arch = "x86_64",
        all(target_arch = "wasm32", target_feature = "simd128")
    )
))]
fn lane_cap() -> usize {
    static CAP: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *CAP.get_or_init(|| match std::env::var("SCREWBENDER_MAX_LANES") {
        Err(std::env::VarError::NotPresent) => usize::MAX,
        Ok(v) if v.is_empty() => usize::MAX,
        Ok(v) if matches!(v.as_str(), "8" | "4" | "2") => v.parse().expect("checked digits"),
        Ok(v) => panic!("SCREWBENDER_MAX_LANES={v:?}: expected 8, 4 or 2"),
        Err(e) => panic!("SCREWBENDER_MAX_LANES: {e}"),
    })
}

/// The cap on the lanes' width that tests set, so that they cover the narrower routes on
/// machines that have wider ones.
#[cfg(test)]
pub(crate) mod tests {
    use std::cell::Cell;

    thread_local! {
        static MAX_WIDTH: Cell<usize> = const { Cell::new(usize::MAX) };
    }

    /// Runs `f` with the batches on at most `width` lanes (8, 4 or 2), so that tests cover the
    /// narrower routes on machines that have wider ones.
    pub(crate) fn with_max_width<T>(width: usize, f: impl FnOnce() -> T) -> T {
        MAX_WIDTH.with(|w| w.set(width));
        let result = f();
        MAX_WIDTH.with(|w| w.set(usize::MAX));
        result
    }

    /// The cap set by [`with_max_width`] on this thread.
    pub(crate) fn max_width() -> usize {
        MAX_WIDTH.with(Cell::get)
    }
}
