//! Help for each command, shell completion scripts, the manual page, and usage errors that point
//! at the command's own help.
#![cfg(not(target_arch = "wasm32"))]

mod support;

use support::run;

/// The commands, as `screwbender --help` lists them.
const COMMANDS: [&str; 11] = [
    "subdivide",
    "eval",
    "screw",
    "preset",
    "compare",
    "rational",
    "export",
    "import",
    "fit",
    "completions",
    "man",
];

/// `screwbender ARGS` succeeds, writes nothing on standard error, and prints text containing
/// every string of `want`; returns the text.
#[track_caller]
fn prints(args: &[&str], want: &[&str]) -> String {
    let out = run(args, "");
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    assert!(out.stderr.is_empty(), "{args:?}: {}", out.stderr);
    for w in want {
        assert!(
            out.stdout.contains(w),
            "{args:?} lacks '{w}':\n{}",
            out.stdout
        );
    }
    out.stdout
}

/// `screwbender ARGS` fails as bad usage: exit status 2, nothing on standard output, one line
/// on standard error starting `screwbender: `; returns that line.
#[track_caller]
fn refuses(args: &[&str]) -> String {
    let out = run(args, "");
    assert_eq!(out.code, 2, "{args:?}: exit {} ({})", out.code, out.stderr);
    assert!(out.stdout.is_empty(), "{args:?}: printed {}", out.stdout);
    assert_eq!(out.stderr.lines().count(), 1, "{args:?}: {}", out.stderr);
    assert!(
        out.stderr.starts_with("screwbender: "),
        "{args:?}: {}",
        out.stderr
    );
    out.stderr
}

#[test]
fn each_command_has_its_own_help() {
    prints(
        &["compare", "--help"],
        &[
            "Usage: screwbender compare",
            "--methods",
            "--json",
            "--open",
        ],
    );
    prints(
        &["export", "--help"],
        &[
            "Usage: screwbender export",
            "--tolerance",
            "--fps",
            "--format",
            "--velocities",
            // The shared subdivision options, and what the glTF asset holds.
            "--scheme",
            "--levels",
            "'control poses'",
        ],
    );
    // The commands that read a motion document describe it.
    for command in [
        "subdivide",
        "eval",
        "screw",
        "compare",
        "rational",
        "export",
    ] {
        prints(&[command, "--help"], &["FILE is a JSON motion document"]);
    }
    for command in COMMANDS {
        prints(
            &[command, "--help"],
            &[&format!("Usage: screwbender {command}")],
        );
        // `-h`, the summary, also works.
        prints(
            &[command, "-h"],
            &[&format!("Usage: screwbender {command}")],
        );
    }
    // `help COMMAND` is the same as `COMMAND --help`.
    let help = prints(&["help", "compare"], &["--methods", "--json"]);
    assert_eq!(help, prints(&["compare", "--help"], &[]));
}

#[test]
fn completion_scripts_name_every_command() {
    for shell in ["bash", "zsh", "fish"] {
        let script = prints(&["completions", shell], &["screwbender"]);
        let words: Vec<&str> = script
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .collect();
        for command in COMMANDS {
            assert!(words.contains(&command), "{shell}: no {command}");
        }
        // Options of the commands complete too.
        assert!(
            script.contains("methods") && script.contains("tolerance"),
            "{shell}"
        );
    }
    let line = refuses(&["completions", "nope"]);
    assert!(line.contains("'nope'") && line.contains("bash"), "{line}");
    refuses(&["completions"]);
}

#[test]
fn man_page_is_roff() {
    let page = prints(&["man"], &[".SH NAME", ".SH SYNOPSIS"]);
    // clap_mangen defines the roff string it quotes with first; the page proper starts at .TH.
    let th = page
        .lines()
        .position(|l| l.starts_with(".TH screwbender 1"))
        .unwrap_or_else(|| panic!("no .TH line:\n{page}"));
    assert!(page.lines().take(th).all(|l| l.starts_with('.')), "{page}");
    for command in COMMANDS {
        assert!(
            page.contains(&format!("screwbender\\-{command}")),
            "no {command}"
        );
    }
    // Each command has its own page, the one the list above refers to.
    let page = prints(&["man", "export"], &[".SH OPTIONS", "tolerance", "fps"]);
    assert!(page.contains("\n.TH screwbender-export 1"), "{page}");
    let line = refuses(&["man", "nope"]);
    assert!(line.contains("'nope'"), "{line}");
}

#[test]
fn usage_errors_point_at_the_command_help() {
    let line = refuses(&["compare", "--frobnicate"]);
    assert!(
        line.contains("'--frobnicate'") && line.contains("screwbender compare --help"),
        "{line}"
    );
    let line = refuses(&["export", "--format", "csv", "--levels"]);
    assert!(line.contains("--levels needs a value"), "{line}");
    let line = refuses(&["export", "--format", "csv", "-o"]);
    assert!(line.contains("-o needs a value"), "{line}");
    let line = refuses(&["preset", "circle4", "pendulum"]);
    assert!(line.contains("'pendulum'"), "{line}");
    // Values the CLI checks itself keep their own words, without a pointer.
    let line = refuses(&["eval", "--u", "x"]);
    assert_eq!(line, "screwbender: --u: 'x' is not a finite number\n");
}
