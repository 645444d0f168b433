//! `screwbender compare [--methods a,b,c] [--json] [FILE]`: the metrics of the comparison
//! methods on one set of control poses, as an aligned text table or JSON.

use screwbender::methods::{compare_applicable, compare_methods, Method, MetricsOptions};
use screwbender::{Error, Pose};

/// The comparison table of the named `methods` on `poses` (pose `i` at parameter `u = i`; a
/// closed input is a cycle of period `n`).
///
/// Names are those of [`Method::NAMES`]; each entry may also be a comma-separated list
/// (`"rb,cc0"`), duplicates are measured once. With no names, every method that applies is used
/// (all but `cc1` for a closed input), and one that does not support these particular poses is
/// listed as skipped. An unknown name gives [`Error::UnknownValue`] at `methods`; a named method
/// that rejects the input (e.g. `cc1` on a closed input) gives its error, prefixed with the
/// method's name. A motion that is poor though it was built ([`Method::warnings`]) is noted in
/// its row and gets a `screwbender: warning: METHOD: …` line on standard error.
pub fn compare(
    poses: &[Pose],
    closed: bool,
    methods: &[String],
    json: bool,
) -> Result<String, Error> {
    let mut chosen: Vec<Method> = Vec::new();
    for entry in methods {
        for name in entry.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let m: Method = name.parse()?;
            if !chosen.contains(&m) {
                chosen.push(m);
            }
        }
    }
    let options = MetricsOptions::default();
    let table = if chosen.is_empty() {
        compare_applicable(poses, closed, &options)?
    } else {
        compare_methods(poses, closed, &chosen, &options)?
    };
    // Where a motion is poor though it was built: one line each on standard error.
    for row in &table.rows {
        for note in &row.notes {
            if let Some(w) = note.strip_prefix("warning: ") {
                eprintln!("screwbender: warning: {}: {w}", row.method);
            }
        }
    }
    Ok(if json {
        table.to_json() + "\n"
    } else {
        table.to_text()
    })
}
