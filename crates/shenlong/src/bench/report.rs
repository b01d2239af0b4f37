//! Benchmark reports: figures per system and category, tests of significance between
//! systems, Markdown beside the paper's figures, and charts.

use super::run::Outcome;
use super::stats::{mean_std, welch};
use super::suite::CATEGORIES;
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write;

/// The paper's figures (gpt-4-1106-preview, human-judged): success rate, mean response s.
pub const PAPER: [(&str, f64, f64); 3] = [
    ("cga", 0.80, 18.0),
    ("omniverse", 0.74, 21.5),
    ("euclidean", 0.72, 24.5),
];

/// Figures for one group of outcomes.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Figures {
    /// Outcomes counted.
    pub n: usize,
    /// Share that passed every check.
    pub success_rate: f64,
    /// Mean response time, ms.
    pub response_ms_mean: f64,
    /// Its standard deviation, ms.
    pub response_ms_std: f64,
    /// Mean retries.
    pub retries_mean: f64,
    /// Tokens sent, in all.
    pub prompt_tokens: u64,
    /// Tokens received, in all.
    pub completion_tokens: u64,
    /// Answers served from the cache.
    pub cache_hits: usize,
    /// Edits that failed outright (no usable answer).
    pub errors: usize,
    /// Model replies received, retries included (the offline translator sends none).
    pub replies: usize,
    /// Share of the replies that parse (the answer was found; its expressions are well
    /// formed), scored apart from geometry.
    pub parse_rate: f64,
    /// Share of the replies that evaluate to a valid `T·R·D` for every variable.
    pub valid_rate: f64,
    /// Retries spent, in all.
    pub retries_total: usize,
    /// Instances the offline translator answered (for a cascade, its share is
    /// `answered_offline / n`).
    pub answered_offline: usize,
    /// Instances a model answered.
    pub answered_by_model: usize,
    /// Share of the offline-answered instances that passed.
    pub offline_success_rate: f64,
    /// Share of the model-answered instances that passed.
    pub model_success_rate: f64,
}

impl Figures {
    fn of<'a>(outcomes: impl Iterator<Item = &'a Outcome>) -> Self {
        let list: Vec<&Outcome> = outcomes.collect();
        let times: Vec<f64> = list.iter().map(|o| o.response_ms).collect();
        let (mean, std) = mean_std(&times);
        let n = list.len();
        let received: usize = list.iter().map(|o| o.replies.received).sum();
        let offline: Vec<&&Outcome> = list
            .iter()
            .filter(|o| o.answered_by.as_deref() == Some("offline"))
            .collect();
        let model: Vec<&&Outcome> = list
            .iter()
            .filter(|o| o.answered_by.as_deref().is_some_and(|a| a != "offline"))
            .collect();
        Self {
            n,
            success_rate: if n == 0 {
                f64::NAN
            } else {
                list.iter().filter(|o| o.success).count() as f64 / n as f64
            },
            response_ms_mean: mean,
            response_ms_std: std,
            retries_mean: if n == 0 {
                f64::NAN
            } else {
                list.iter().map(|o| o.retries as f64).sum::<f64>() / n as f64
            },
            prompt_tokens: list.iter().map(|o| o.prompt_tokens).sum(),
            completion_tokens: list.iter().map(|o| o.completion_tokens).sum(),
            cache_hits: list.iter().filter(|o| o.cache_hit).count(),
            errors: list.iter().filter(|o| o.error.is_some()).count(),
            replies: received,
            parse_rate: share(list.iter().map(|o| o.replies.parsed).sum(), received),
            valid_rate: share(list.iter().map(|o| o.replies.valid).sum(), received),
            retries_total: list.iter().map(|o| o.retries).sum(),
            answered_offline: offline.len(),
            answered_by_model: model.len(),
            offline_success_rate: share(
                offline.iter().filter(|o| o.success).count(),
                offline.len(),
            ),
            model_success_rate: share(model.iter().filter(|o| o.success).count(), model.len()),
        }
    }
}

/// `part / whole`, or NaN for none.
fn share(part: usize, whole: usize) -> f64 {
    if whole == 0 {
        f64::NAN
    } else {
        part as f64 / whole as f64
    }
}

/// One system's figures.
#[derive(Clone, Debug, Serialize)]
pub struct SystemReport {
    /// Over every instance.
    pub overall: Figures,
    /// Per category.
    pub categories: BTreeMap<String, Figures>,
    /// Per query: the share of its instances that passed.
    pub queries: BTreeMap<String, f64>,
}

/// A Welch t-test between two systems.
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    /// First system.
    pub a: String,
    /// Second system.
    pub b: String,
    /// What was compared: `success` (0/1 per instance) or `response_ms`.
    pub measure: String,
    /// t statistic.
    pub t: f64,
    /// Welch–Satterthwaite degrees of freedom.
    pub df: f64,
    /// Two-sided p-value.
    pub p: f64,
}

/// The whole report (`report.json`).
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// The suite's name.
    pub suite: String,
    /// The translator (offline, or the model).
    pub model: String,
    /// Per system.
    pub systems: BTreeMap<String, SystemReport>,
    /// Tests between every pair of systems.
    pub comparisons: Vec<Comparison>,
    /// Every failed instance with its reasons.
    pub failures: Vec<Outcome>,
    /// Shards `K/N` of a merged run that were not among its folders (the report covers
    /// the rest); absent when none is missing.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub missing_shards: Vec<String>,
}

/// Builds the report from outcomes, in any order: they are sorted by system and instance
/// first, so a run split into shards and merged gives the same figures as one run.
pub fn build(suite: &str, model: &str, outcomes: &[Outcome]) -> Report {
    let mut sorted: Vec<Outcome> = outcomes.to_vec();
    sorted.sort_by(|a, b| (&a.system, &a.instance).cmp(&(&b.system, &b.instance)));
    let outcomes = sorted.as_slice();
    let mut systems = BTreeMap::new();
    let names: Vec<String> = {
        let mut n: Vec<String> = outcomes.iter().map(|o| o.system.clone()).collect();
        n.sort();
        n.dedup();
        n
    };
    for system in &names {
        let mine: Vec<&Outcome> = outcomes.iter().filter(|o| &o.system == system).collect();
        let mut categories = BTreeMap::new();
        for category in CATEGORIES {
            let f = Figures::of(mine.iter().copied().filter(|o| o.category == category));
            if f.n > 0 {
                categories.insert(category.to_string(), f);
            }
        }
        let mut queries: BTreeMap<String, (usize, usize)> = BTreeMap::new();
        for o in &mine {
            let e = queries.entry(o.query.clone()).or_default();
            e.0 += o.success as usize;
            e.1 += 1;
        }
        systems.insert(
            system.clone(),
            SystemReport {
                overall: Figures::of(mine.iter().copied()),
                categories,
                queries: queries
                    .into_iter()
                    .map(|(q, (ok, n))| (q, ok as f64 / n as f64))
                    .collect(),
            },
        );
    }
    let mut comparisons = Vec::new();
    for (i, a) in names.iter().enumerate() {
        for b in &names[i + 1..] {
            let pick = |s: &String, f: fn(&Outcome) -> f64| -> Vec<f64> {
                outcomes.iter().filter(|o| &o.system == s).map(f).collect()
            };
            for (measure, f) in [
                (
                    "success",
                    (|o: &Outcome| o.success as u8 as f64) as fn(&Outcome) -> f64,
                ),
                ("response_ms", |o: &Outcome| o.response_ms),
            ] {
                if let Some((t, df, p)) = welch(&pick(a, f), &pick(b, f)) {
                    comparisons.push(Comparison {
                        a: a.clone(),
                        b: b.clone(),
                        measure: measure.into(),
                        t,
                        df,
                        p,
                    });
                }
            }
        }
    }
    let failures = outcomes.iter().filter(|o| !o.success).cloned().collect();
    Report {
        suite: suite.into(),
        model: model.into(),
        systems,
        comparisons,
        failures,
        missing_shards: Vec::new(),
    }
}

fn pct(x: f64) -> String {
    if x.is_nan() {
        "—".into()
    } else {
        format!("{:.1} %", x * 100.0)
    }
}

fn secs(ms: f64) -> String {
    if ms.is_nan() {
        "—".into()
    } else if ms < 1000.0 {
        format!("{ms:.2} ms")
    } else {
        format!("{:.2} s", ms / 1000.0)
    }
}

/// Every (system, category, figures) row of the tables, each system's categories then its
/// overall figures under the label `overall`.
fn rows<'a>(
    report: &'a Report,
    overall: &'a str,
) -> impl Iterator<Item = (&'a str, &'a str, &'a Figures)> {
    report.systems.iter().flat_map(move |(system, r)| {
        r.categories
            .iter()
            .map(|(c, f)| (c.as_str(), f))
            .chain(std::iter::once((overall, &r.overall)))
            .map(move |(c, f)| (system.as_str(), c, f))
    })
}

/// The summary table printed at the end of a run.
pub fn summary(report: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{:<11} {:<20} {:>6} {:>9} {:>12} {:>8}",
        "system", "category", "n", "success", "response", "retries"
    );
    for (system, category, f) in rows(report, "overall") {
        let _ = writeln!(
            out,
            "{system:<11} {category:<20} {:>6} {:>9} {:>12} {:>8.2}",
            f.n,
            pct(f.success_rate),
            secs(f.response_ms_mean),
            f.retries_mean
        );
    }
    out
}

/// The Markdown report.
pub fn markdown(report: &Report) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Benchmark: {}\n\nTranslator: `{}`.\n",
        report.suite, report.model
    );
    if !report.missing_shards.is_empty() {
        let _ = writeln!(
            md,
            "**Partial**: shard(s) {} are missing; the figures cover the other shards.\n",
            report.missing_shards.join(", ")
        );
    }
    let _ = writeln!(md, "## Success rate and response time\n");
    let _ = writeln!(md, "| system | category | n | success | response (mean ± sd) | retries | tokens in / out | cache hits |\n|---|---|---|---|---|---|---|---|");
    for (system, category, f) in rows(report, "**overall**") {
        let _ = writeln!(
            md,
            "| {system} | {category} | {} | {} | {} ± {} | {:.2} | {} / {} | {} |",
            f.n,
            pct(f.success_rate),
            secs(f.response_ms_mean),
            secs(f.response_ms_std),
            f.retries_mean,
            f.prompt_tokens,
            f.completion_tokens,
            f.cache_hits
        );
    }
    let _ = writeln!(md, "\n## What went wrong, by kind\n\nReplies are scored apart from geometry: the share of the model's replies (retries included) that parse, and that evaluate to a valid T·R·D; then the share of instances that pass the checks. A cascade's instances are split by the part that answered.\n\n| system | category | replies | parse | valid T·R·D | pass | retries | answered offline | pass (offline) | pass (model) |\n|---|---|---|---|---|---|---|---|---|---|");
    for (system, category, f) in rows(report, "**overall**") {
        let _ = writeln!(
            md,
            "| {system} | {category} | {} | {} | {} | {} | {} | {} | {} | {} |",
            f.replies,
            pct(f.parse_rate),
            pct(f.valid_rate),
            pct(f.success_rate),
            f.retries_total,
            pct(share(f.answered_offline, f.n)),
            pct(f.offline_success_rate),
            pct(f.model_success_rate)
        );
    }
    let _ = writeln!(md, "\n## Beside the paper\n\nThe paper (gpt-4-1106-preview, 10 Holodeck scenes × 5 categories × 10 queries × 5 variations, judged by people):\n\n| system | paper: success | paper: response | here: success | here: response |\n|---|---|---|---|---|");
    for (system, success, seconds) in PAPER {
        let here = report.systems.get(system);
        let _ = writeln!(
            md,
            "| {system} | {} | {seconds} s | {} | {} |",
            pct(success),
            here.map_or("—".into(), |r| pct(r.overall.success_rate)),
            here.map_or("—".into(), |r| secs(r.overall.response_ms_mean))
        );
    }
    if !report.comparisons.is_empty() {
        let _ = writeln!(md, "\n## Tests of significance (Welch's t-test, two-sided)\n\n| systems | measure | t | df | p |\n|---|---|---|---|---|");
        for c in &report.comparisons {
            let _ = writeln!(
                md,
                "| {} vs {} | {} | {:.3} | {:.1} | {:.4} |",
                c.a, c.b, c.measure, c.t, c.df, c.p
            );
        }
    }
    let _ = writeln!(
        md,
        "\n## Charts\n\n![success rate](success.svg)\n\n![response time](response.svg)\n\n![replies that parse](parse.svg)\n\n![replies that evaluate to a valid T·R·D](valid.svg)\n"
    );
    let _ = writeln!(md, "## Failures ({})\n", report.failures.len());
    for o in report.failures.iter().take(200) {
        let why = o.error.clone().unwrap_or_else(|| o.failures.join("; "));
        let _ = writeln!(
            md,
            "- `{}` [{}] {}: {}",
            o.instance,
            o.system,
            o.instruction.replace('|', "\\|"),
            why.replace('|', "\\|")
        );
    }
    if report.failures.len() > 200 {
        let _ = writeln!(
            md,
            "- … and {} more (report.json has them all)",
            report.failures.len() - 200
        );
    }
    md
}

/// A grouped bar chart: categories along x, one bar per system, the overall means as
/// dashed lines, like the paper's figure.
pub fn chart(report: &Report, title: &str, value: fn(&Figures) -> f64, unit: &str) -> String {
    const COLOURS: [&str; 3] = ["#2f6db3", "#e07b28", "#3a9a4a"];
    let (w, h, left, bottom, top) = (900.0, 420.0, 70.0, 60.0, 50.0);
    let systems: Vec<(&String, &SystemReport)> = report.systems.iter().collect();
    let cats: Vec<&str> = CATEGORIES
        .iter()
        .copied()
        .filter(|c| systems.iter().any(|(_, r)| r.categories.contains_key(*c)))
        .collect();
    let max = systems
        .iter()
        .flat_map(|(_, r)| {
            r.categories
                .values()
                .map(value)
                .chain(std::iter::once(value(&r.overall)))
        })
        .filter(|v| v.is_finite())
        .fold(0.0f64, f64::max)
        .max(1e-9);
    let max = if unit == "%" { 1.0 } else { max * 1.15 };
    let plot_h = h - bottom - top;
    let y = |v: f64| top + plot_h * (1.0 - v / max);
    let group_w = (w - left - 20.0) / cats.len().max(1) as f64;
    let bar_w = group_w * 0.8 / systems.len().max(1) as f64;
    let mut svg = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="DejaVu Sans, Arial, sans-serif"><rect width="100%" height="100%" fill="#fff"/><text x="{left}" y="28" font-size="16" font-weight="bold">{title}</text>"##
    );
    for k in 0..=4 {
        let v = max * k as f64 / 4.0;
        let label = if unit == "%" {
            format!("{:.0}%", v * 100.0)
        } else {
            secs(v)
        };
        let _ = write!(
            svg,
            r##"<line x1="{left}" x2="{}" y1="{:.1}" y2="{:.1}" stroke="#ddd"/><text x="{}" y="{:.1}" font-size="11" text-anchor="end">{label}</text>"##,
            w - 20.0,
            y(v),
            y(v),
            left - 6.0,
            y(v) + 4.0
        );
    }
    for (c, cat) in cats.iter().enumerate() {
        let x0 = left + group_w * c as f64 + group_w * 0.1;
        for (s, (_, r)) in systems.iter().enumerate() {
            if let Some(f) = r.categories.get(*cat) {
                let v = value(f);
                if v.is_finite() {
                    let _ = write!(
                        svg,
                        r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="{}"/>"##,
                        x0 + bar_w * s as f64,
                        y(v),
                        bar_w - 2.0,
                        (y(0.0) - y(v)).max(0.0),
                        COLOURS[s % 3]
                    );
                }
            }
        }
        let _ = write!(
            svg,
            r##"<text x="{:.1}" y="{:.1}" font-size="12" text-anchor="middle">{}</text>"##,
            x0 + group_w * 0.4,
            h - bottom + 18.0,
            cat.replace('_', " ")
        );
    }
    for (s, (name, r)) in systems.iter().enumerate() {
        let v = value(&r.overall);
        if v.is_finite() {
            let _ = write!(
                svg,
                r##"<line x1="{left}" x2="{}" y1="{:.1}" y2="{:.1}" stroke="{}" stroke-width="2" stroke-dasharray="6,4"/>"##,
                w - 20.0,
                y(v),
                y(v),
                COLOURS[s % 3]
            );
        }
        let _ = write!(
            svg,
            r##"<rect x="{:.1}" y="{:.1}" width="12" height="12" fill="{}"/><text x="{:.1}" y="{:.1}" font-size="12">{name} (overall dashed)</text>"##,
            left + 180.0 * s as f64,
            h - 22.0,
            COLOURS[s % 3],
            left + 180.0 * s as f64 + 16.0,
            h - 12.0
        );
    }
    svg.push_str("</svg>\n");
    svg
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::translate::ReplyCounts;

    fn outcome(
        system: &str,
        id: &str,
        success: bool,
        by: Option<&str>,
        r: (usize, usize, usize),
    ) -> Outcome {
        Outcome {
            instance: id.into(),
            query: id.split('@').next().unwrap_or(id).into(),
            category: "simple".into(),
            scene: "s".into(),
            system: system.into(),
            instruction: "move X1".into(),
            success,
            failures: Vec::new(),
            error: None,
            response_ms: 1.0,
            retries: r.0.saturating_sub(1),
            prompt_tokens: 10,
            completion_tokens: 2,
            cache_hit: false,
            answered_by: by.map(str::to_string),
            replies: ReplyCounts {
                received: r.0,
                parsed: r.1,
                valid: r.2,
            },
        }
    }

    #[test]
    fn figures_score_replies_and_the_cascade_parts() {
        let outcomes = vec![
            outcome("cga", "a@s#0", true, Some("offline"), (0, 0, 0)),
            outcome("cga", "b@s#0", true, Some("offline"), (0, 0, 0)),
            outcome("cga", "c@s#0", false, Some("gpt"), (3, 2, 1)),
            outcome("cga", "d@s#0", true, Some("gpt"), (1, 1, 1)),
            outcome("euclidean", "a@s#0", false, None, (6, 3, 0)),
        ];
        let r = build("suite", "offline+gpt", &outcomes);
        let cga = &r.systems["cga"].overall;
        assert_eq!(cga.replies, 4);
        assert_eq!(cga.parse_rate, 0.75);
        assert_eq!(cga.valid_rate, 0.5);
        assert_eq!(cga.success_rate, 0.75);
        assert_eq!(cga.retries_total, 2);
        assert_eq!((cga.answered_offline, cga.answered_by_model), (2, 2));
        assert_eq!(cga.offline_success_rate, 1.0);
        assert_eq!(cga.model_success_rate, 0.5);
        let e = &r.systems["euclidean"].overall;
        assert_eq!((e.parse_rate, e.valid_rate), (0.5, 0.0));
        assert!(e.offline_success_rate.is_nan(), "no part answered offline");
        // The same outcomes in another order give the same report.
        let mut shuffled = outcomes.clone();
        shuffled.reverse();
        let again = build("suite", "offline+gpt", &shuffled);
        assert_eq!(
            serde_json::to_string(&again).unwrap(),
            serde_json::to_string(&r).unwrap()
        );
        let md = markdown(&r);
        assert!(md.contains("| cga | **overall** | 4 | 75.0 % | 50.0 % | 75.0 % | 2 | 50.0 % | 100.0 % | 50.0 % |"), "{md}");
    }
}
