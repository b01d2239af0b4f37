//! `shenlong chat`: a conversation with a scene in the terminal — one instruction a turn,
//! follow-ups that lean on the turn before ("a bit more", "put it back", "and the mug
//! too"), what moved said after each, undo and save as commands. At a terminal it edits
//! lines with history (rustyline); from a pipe it reads one instruction a line.

use anyhow::{Context, Result};
use rustyline::error::ReadlineError;
use shenlong::pipeline::backends::translator;
use shenlong::pipeline::{EditOptions, System, Translator};
use shenlong::session::{EditRequest, How, Moved, OpError, Outcome, Session};
use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;

/// Talk to a scene: one instruction a line, follow-ups included.
///
/// Each line is an instruction ("move the armchair 50 cm to the left") or a follow-up of
/// the one before ("a bit more", "no, the other one", "put it back", "and the ottoman
/// too"); what moved is said after each. Commands start with `/`: /undo, /redo,
/// /history, /save, /select NAME (what "it" means in the next instruction), /help,
/// /quit. The scene is written to the --save file (atomically)
/// on /save and on leaving; without --save nothing is written.
#[derive(clap::Args)]
#[command(after_help = "Examples:
  shenlong chat examples/living_room.json --save edited.json
  printf 'move the armchair 1 m left\\na bit more\\nput it back\\n' | shenlong chat examples/living_room.json --json

From a pipe each line is one turn; with --json each answer is one line of JSON (the
outcome, or the refusal with its kind), and the exit status is 1 when a turn was refused.")]
pub struct Args {
    #[command(flatten)]
    read: super::ReadArgs,
    /// The scene file (or example:NAME).
    scene: String,
    /// Where /save and leaving write the scene (format by extension).
    #[arg(long, value_name = "FILE")]
    save: Option<PathBuf>,
    /// The prompt system: cga (Shenlong), euclidean or omniverse (the paper's baselines).
    #[arg(long, value_name = "SYSTEM", default_value = "cga")]
    system: System,
    /// Answer each turn as one line of JSON on stdout: the outcome, or the refusal.
    #[arg(long)]
    json: bool,
    /// Do not carry the objects resting on a moved object.
    #[arg(long)]
    no_carry: bool,
    #[command(flatten)]
    translator: super::TranslatorArgs,
    #[command(flatten)]
    collisions: super::CollisionArgs,
}

/// What the chat needs for every turn.
struct Chat {
    session: Session,
    /// The objects `/select` chose: what "it" means, over what the last edit moved.
    selected: Vec<String>,
    translator: Box<dyn Translator>,
    options: EditOptions,
    json: bool,
    /// Whether the scene changed since it was last written.
    unsaved: bool,
    refusals: usize,
}

/// What a line asks the chat to do.
enum Line<'a> {
    Nothing,
    Help,
    Undo,
    Redo,
    History,
    Save,
    Quit,
    /// `/select NAME, NAME …` (none: clear the selection).
    Select(&'a str),
    Unknown(&'a str),
    Instruction(&'a str),
}

fn parse(line: &str) -> Line<'_> {
    let line = line.trim();
    match line.to_ascii_lowercase().as_str() {
        "" => Line::Nothing,
        "/help" | "/?" | "help" => Line::Help,
        "/undo" => Line::Undo,
        "/redo" | "redo" => Line::Redo,
        "/history" => Line::History,
        "/save" => Line::Save,
        "/quit" | "/exit" | "/q" | "quit" | "exit" => Line::Quit,
        other if other == "/select" || other.starts_with("/select ") => {
            Line::Select(line["/select".len()..].trim())
        }
        other if other.starts_with('/') => Line::Unknown(line),
        _ => Line::Instruction(line),
    }
}

const HELP: &str =
    "Type an instruction (\"move the armchair 50 cm to the left\") or a follow-up of the last one:
  it / them / that      what the last edit moved
  a bit more, again, twice as far, not so far, more to the left
  no, the other one · no, on the shelf · the left one (after a refusal)
  and the mug too · do the same with the lamp
  put it back · back where it was · undo that
  /select armchair, ottoman   what \"it\" means in the next edit (/select alone clears)
Commands: /undo  /redo  /history  /save  /select  /help  /quit";

pub fn run(args: Args) -> Result<()> {
    let settings = args.translator.settings(args.system)?;
    let file = super::load_scene_with(&args.scene, &args.read)?;
    let translator = translator(&args.translator.llm, &settings).map_err(super::llm_error)?;
    let options = EditOptions::new(!args.no_carry, args.collisions.resolve_options()?);
    let mut chat = Chat {
        session: Session::saving_on_request(file, args.save.clone()),
        selected: Vec::new(),
        translator,
        options,
        json: args.json,
        unsaved: false,
        refusals: 0,
    };
    let interactive = std::io::stdin().is_terminal() && std::io::stdout().is_terminal();
    if interactive {
        chat.interactive()?;
    } else {
        chat.piped()?;
    }
    chat.leave()?;
    if !interactive && chat.refusals > 0 {
        anyhow::bail!(
            "{} refused",
            if chat.refusals == 1 {
                "1 turn was".to_string()
            } else {
                format!("{} turns were", chat.refusals)
            }
        );
    }
    Ok(())
}

impl Chat {
    /// At a terminal: line editing and history until /quit or end of input.
    fn interactive(&mut self) -> Result<()> {
        let scene = &self.session.file.scene;
        println!(
            "{} — {} objects. Type an instruction, or /help.",
            shenlong_cli::terminal::safe(&scene.name),
            scene.objects.len()
        );
        let mut editor = rustyline::DefaultEditor::new().context("cannot read the terminal")?;
        loop {
            match editor.readline("shenlong> ") {
                Ok(line) => {
                    let _ = editor.add_history_entry(line.as_str());
                    if !self.turn(&line)? {
                        return Ok(());
                    }
                }
                // Ctrl-C drops the line being typed; Ctrl-D leaves.
                Err(ReadlineError::Interrupted) => continue,
                Err(ReadlineError::Eof) => return Ok(()),
                Err(e) => return Err(e).context("cannot read the terminal"),
            }
        }
    }

    /// From a pipe: one turn a line.
    fn piped(&mut self) -> Result<()> {
        for line in std::io::stdin().lock().lines() {
            let line = line.context("cannot read standard input")?;
            if !self.turn(&line)? {
                break;
            }
        }
        Ok(())
    }

    /// One line; `false` to leave.
    fn turn(&mut self, line: &str) -> Result<bool> {
        let answer = match parse(line) {
            Line::Nothing => return Ok(true),
            Line::Quit => return Ok(false),
            Line::Help => {
                println!("{HELP}");
                return Ok(true);
            }
            Line::History => {
                for h in self.session.history() {
                    let state = if h.undone { " (undone)" } else { "" };
                    println!(
                        "{:>3}  {}{state}",
                        h.id,
                        shenlong_cli::terminal::safe(&h.text)
                    );
                }
                return Ok(true);
            }
            Line::Save => {
                self.save()?;
                return Ok(true);
            }
            Line::Select(names) => {
                self.select(names);
                return Ok(true);
            }
            Line::Unknown(command) => {
                say(&format!("unknown command {command}: /help lists them"));
                return Ok(true);
            }
            Line::Undo => self.session.undo(),
            Line::Redo => self.session.redo(),
            Line::Instruction(text) => {
                let request = EditRequest {
                    instruction: text,
                    selected: &self.selected,
                    report: false,
                };
                let answer = self
                    .session
                    .edit(&request, self.translator.as_ref(), &self.options);
                // A selection holds for one edit, as a click in the editor does.
                if answer.is_ok() {
                    self.selected.clear();
                }
                answer
            }
        };
        self.answer(answer)?;
        Ok(true)
    }

    /// Selects the objects named (comma-separated), each as the scene names it.
    fn select(&mut self, names: &str) {
        let scene = &self.session.file.scene;
        let mut chosen = Vec::new();
        for name in names.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            match scene.resolve(name) {
                Ok(i) => chosen.push(scene.objects[i].name.clone()),
                Err(e) => {
                    say(&format!("/select: {e}"));
                    return;
                }
            }
        }
        self.selected = chosen;
        if !self.json {
            match self.selected.as_slice() {
                [] => println!("  nothing selected"),
                names => println!(
                    "  selected: {} — \"it\" means {}",
                    shenlong_cli::terminal::safe(&names.join(", ")),
                    if names.len() == 1 { "it" } else { "them" }
                ),
            }
        }
    }

    /// Says what a turn did, or why it was refused.
    fn answer(&mut self, answer: Result<Outcome, OpError>) -> Result<()> {
        let mut out = std::io::stdout().lock();
        match answer {
            Ok(outcome) => {
                self.unsaved |= !outcome.moved.is_empty();
                if self.json {
                    writeln!(out, "{}", serde_json::to_string(&outcome)?)?;
                } else {
                    for moved in &outcome.moved {
                        writeln!(out, "  {}", describe(moved))?;
                    }
                    if outcome.moved.is_empty() {
                        writeln!(out, "  nothing moved")?;
                    }
                    for note in &outcome.notes {
                        writeln!(out, "  note: {}", shenlong_cli::terminal::safe(note))?;
                    }
                }
            }
            Err(refusal) => {
                self.refusals += 1;
                if self.json {
                    writeln!(out, "{}", serde_json::to_string(&refusal)?)?;
                } else {
                    say(&refusal.message);
                }
            }
        }
        Ok(())
    }

    /// Writes the scene to the --save file.
    fn save(&mut self) -> Result<()> {
        let Some(path) = self.session.save_path().map(PathBuf::from) else {
            say("nothing to save to: start the chat with --save FILE");
            return Ok(());
        };
        self.session.save()?;
        self.unsaved = false;
        if !self.json {
            println!(
                "  saved {}",
                shenlong_cli::terminal::safe(&path.display().to_string())
            );
        }
        Ok(())
    }

    /// On leaving: the scene written to the --save file when it changed.
    fn leave(&mut self) -> Result<()> {
        if self.unsaved {
            if self.session.save_path().is_some() {
                self.save()?;
            } else {
                say("the changes were not written: start the chat with --save FILE to keep them");
            }
        }
        Ok(())
    }
}

/// Prints a refusal or a problem on stderr, made safe.
fn say(message: &str) {
    shenlong_cli::say!("shenlong: {message}");
}

/// One moved object in words: how far and which way, turned, scaled, and why.
fn describe(moved: &Moved) -> String {
    let [x0, y0, z0] = moved.before.position;
    let [x1, y1, z1] = moved.after.position;
    let (dx, dy, dz) = (x1 - x0, y1 - y0, z1 - z0);
    let mut parts = Vec::new();
    let distance = (dx * dx + dy * dy + dz * dz).sqrt();
    if distance > 1e-6 {
        parts.push(format!(
            "moved {distance:.2} m (x {dx:+.2}, y {dy:+.2}, z {dz:+.2})"
        ));
    }
    let q0 = glam::DQuat::from_array(moved.before.rotation);
    let q1 = glam::DQuat::from_array(moved.after.rotation);
    let angle = q0.angle_between(q1).to_degrees();
    if angle > 0.01 {
        parts.push(format!("turned {angle:.0}°"));
    }
    if (moved.after.scale / moved.before.scale - 1.0).abs() > 1e-9 {
        parts.push(format!(
            "scaled ×{:.2}",
            moved.after.scale / moved.before.scale
        ));
    }
    let why = match moved.how {
        How::Moved => "",
        How::Carried => " (carried)",
        How::Pushed => " (pushed out of the way)",
    };
    format!(
        "'{}': {}{why}",
        shenlong_cli::terminal::safe(&moved.object),
        parts.join(", ")
    )
}
