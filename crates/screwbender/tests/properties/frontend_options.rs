//! The front ends' shared option rules (screwbender::frontend::options): ids, aliases, the
//! agreement of `scheme` and `s`, the level cap and its reason, the default.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

use screwbender::frontend::{
    default_subdivision, parse_levels, parse_levels_text, resolve, OptionsInput, DEFAULT_LEVELS,
    MAX_LEVELS,
};
use screwbender::{Rules, Scheme, Subdivision};

fn input<'a>() -> OptionsInput<'a> {
    OptionsInput::default()
}

#[test]
fn the_default_is_four_point_direct_five_levels_everywhere() {
    let d = Subdivision::default();
    assert_eq!(d, default_subdivision());
    assert_eq!(
        (d.scheme, d.rules, d.levels),
        (Scheme::FourPoint, Rules::Direct, DEFAULT_LEVELS)
    );
    assert_eq!(DEFAULT_LEVELS, 5);
}

#[test]
fn the_level_cap_is_where_no_input_fits_the_memory_guard() {
    // Two poses as a cycle, the fewest a motion has, fit at MAX_LEVELS and never above.
    let at = |levels| Subdivision::new(Scheme::FourPoint, Rules::Direct, levels);
    assert!(at(MAX_LEVELS).output_len(2, true).is_ok());
    assert!(at(MAX_LEVELS + 1).output_len(2, true).is_err());
    assert_eq!(parse_levels(MAX_LEVELS as f64).unwrap(), MAX_LEVELS);
    for bad in [
        MAX_LEVELS as f64 + 1.0,
        -1.0,
        2.5,
        f64::NAN,
        f64::INFINITY,
        1e300,
    ] {
        let e = parse_levels(bad).unwrap_err();
        assert_eq!(e.path(), "levels", "{bad}");
        assert!(
            e.to_string().contains(&format!("from 0 to {MAX_LEVELS}")),
            "{e}"
        );
    }
    assert_eq!(parse_levels_text(" 3 ").unwrap(), 3);
    assert_eq!(
        parse_levels_text("two").unwrap_err().to_string(),
        "levels: 'two' is not a level count (expected a whole number)"
    );
}

#[test]
fn scheme_and_s_resolve_one_way() {
    let base = Subdivision::default();
    let r = |i: OptionsInput| resolve(base, &i);
    // s alone: the J_s family; with j: the parameter; with a named scheme: must agree.
    assert_eq!(
        r(OptionsInput {
            s: Some(0.25),
            ..input()
        })
        .unwrap()
        .scheme,
        Scheme::J(0.25)
    );
    let j = OptionsInput {
        scheme: Some("j"),
        s: Some(0.75),
        ..input()
    };
    assert_eq!(r(j).unwrap().scheme, Scheme::J(0.75));
    let agree = OptionsInput {
        scheme: Some("bspline"),
        s: Some(1.0),
        ..input()
    };
    assert_eq!(r(agree).unwrap().scheme, Scheme::BSpline);
    let e = r(OptionsInput {
        scheme: Some("bspline"),
        s: Some(0.3),
        ..input()
    })
    .unwrap_err();
    assert_eq!(e.path(), "s");
    assert!(
        e.to_string().contains("contradicts scheme 'bspline'"),
        "{e}"
    );
    // The rule set's id is `split`, with the long form accepted.
    for name in ["split", "split-then-tweak"] {
        let i = OptionsInput {
            rules: Some(name),
            ..input()
        };
        assert_eq!(r(i).unwrap().rules, Rules::SplitThenTweak);
    }
    // Errors name the option, and nothing else changes.
    let e = r(OptionsInput {
        scheme: Some("cubic"),
        ..input()
    })
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek, j)"
    );
    let e = r(OptionsInput {
        s: Some(0.5),
        rules: Some("split"),
        ..input()
    })
    .unwrap_err();
    assert_eq!(e.path(), "rules");
    let e = r(OptionsInput {
        s: Some(1.0),
        j: Some(2.0),
        ..input()
    })
    .unwrap_err();
    assert!(e.to_string().contains("disagree"), "{e}");
}
