//! `shenlong`: edit 3D scenes by plain instruction.
//!
//! A thin command line over the `shenlong` library: each subcommand parses its arguments,
//! calls the library, and prints. Errors end the process with one line on stderr and a
//! non-zero status; files are only ever written whole.

mod commands;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Edit 3D scenes by plain instruction, with conformal geometric algebra.
#[derive(Parser)]
#[command(name = "shenlong", version, about, long_about = None, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    Edit(commands::edit::Args),
    Chat(commands::chat::Args),
    Eval(commands::eval::Args),
    Apply(commands::apply::Args),
    Bench(commands::bench::Args),
    Convert(commands::convert::Args),
    Examples(commands::examples::Args),
    Render(commands::render::Args),
    Serve(commands::serve::Args),
    Mcp(commands::mcp::Args),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            use clap::error::ErrorKind;
            if matches!(
                e.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) {
                let _ = e.print();
                return ExitCode::SUCCESS;
            }
            // One line, as every other error: what is wrong, and where to look.
            let text = e.to_string();
            let first = text
                .lines()
                .map(str::trim)
                .find(|l| !l.is_empty())
                .unwrap_or("invalid arguments")
                .trim_start_matches("error: ");
            let tip = text
                .lines()
                .map(str::trim)
                .find_map(|l| l.strip_prefix("tip: "))
                .map(|t| format!(" ({t})"))
                .unwrap_or_default();
            shenlong_cli::say!("shenlong: {first}{tip}; see 'shenlong --help'");
            return ExitCode::from(2);
        }
    };
    let result = match cli.command {
        Command::Edit(args) => commands::edit::run(args),
        Command::Chat(args) => commands::chat::run(args),
        Command::Eval(args) => commands::eval::run(args),
        Command::Apply(args) => commands::apply::run(args),
        Command::Bench(args) => commands::bench::run_bench(args),
        Command::Convert(args) => commands::convert::run(args),
        Command::Examples(args) => commands::examples::run(args),
        Command::Render(args) => commands::render::run(args),
        Command::Serve(args) => commands::serve::run(args),
        Command::Mcp(args) => commands::mcp::run(args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            shenlong_cli::say!("shenlong: {}", one_line(&error));
            ExitCode::FAILURE
        }
    }
}

/// The error and its causes in one line, each said once: the library's errors say their
/// cause in their own message (for callers that print only that) and keep it as their
/// source too, so a cause already said is not repeated.
fn one_line(error: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in error.chain() {
        let text = cause.to_string();
        if !line.contains(&text) {
            if !line.is_empty() {
                line.push_str(": ");
            }
            line.push_str(&text);
        }
    }
    line.replace('\n', " ")
}
