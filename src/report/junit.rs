//! `junit.xml`: one testcase per case × rasterizer, for CI systems that
//! read JUnit. Failures carry the reasons; unsupported cases are skipped;
//! unreadable cases and broken rasterizers are errors. A foil's departures
//! are reported as passing testcases with the departure in `system-out`,
//! since they are expected. A flaky result (`run --repeat`) is a failure
//! whose message starts `flaky: `.

use super::escape::escape;
use std::io::Write;

use super::json::{CaseEntry, Cases, Report};

/// `junit.xml` for a report whose cases are in memory.
pub fn render(report: &Report) -> String {
    let tests: usize = report.cases.iter().map(|c| c.results.len().max(1)).sum();
    let mut xml = Vec::new();
    let mut each = |f: &mut dyn FnMut(&CaseEntry)| {
        report.cases.iter().for_each(&mut *f);
        Ok(())
    };
    write(&mut xml, report, tests, &mut each).expect("a Vec takes every write");
    String::from_utf8(xml).expect("the XML is UTF-8")
}

/// Writes `junit.xml` to `out` for `report` (its totals and rasterizers;
/// its cases are not read) whose cases `cases` hands over, in order, once
/// per rasterizer: `tests` testcases in all (one per result of each case,
/// or one for a case without results).
pub fn write(
    out: &mut dyn Write,
    report: &Report,
    tests: usize,
    cases: &mut Cases,
) -> Result<(), String> {
    let mut failed: Option<std::io::Error> = None;
    let mut put = |out: &mut dyn Write, text: &str| {
        if failed.is_none() {
            if let Err(e) = out.write_all(text.as_bytes()) {
                failed = Some(e);
            }
        }
    };
    put(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let t = &report.totals;
    let failures: usize = t
        .verdicts
        .iter()
        .map(|v| v.tally.fail + v.tally.flaky)
        .sum();
    let errors: usize = t.verdicts.iter().map(|v| v.tally.error).sum::<usize>()
        + t.unreadable
        + t.reference_failed
        + t.limit_exceeded;
    put(out, &format!(
        "<testsuites name=\"rastercheck\" tests=\"{tests}\" failures=\"{failures}\" errors=\"{errors}\">\n"
    ));
    for (k, rasterizer) in report.rasterizers.iter().enumerate() {
        let tally = &t.verdicts[k].tally;
        let suite_tests = t.cases - t.not_run;
        put(out, &format!(
            "  <testsuite name=\"{}\" tests=\"{suite_tests}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\">\n",
            escape(&rasterizer.name),
            tally.fail + tally.flaky,
            tally.error + t.unreadable + t.reference_failed + t.limit_exceeded,
            tally.unsupported
        ));
        cases(&mut |case| put(out, &testcase(&rasterizer.name, k, case)))?;
        put(out, "  </testsuite>\n");
    }
    put(out, "</testsuites>\n");
    match failed {
        Some(e) => Err(format!("junit.xml: {e}")),
        None => Ok(()),
    }
}

/// One case's testcase for the `k`-th rasterizer, `rasterizer`; nothing
/// for a case that did not run.
fn testcase(rasterizer: &str, k: usize, case: &CaseEntry) -> String {
    let classname = format!("{}.{}", escape(rasterizer), escape(&case.family));
    let time = case.results.get(k).map_or(0.0, |r| r.time_ms / 1000.0);
    let open = format!(
        "    <testcase name=\"{}\" classname=\"{classname}\" time=\"{time:.6}\"",
        escape(&case.id)
    );
    if case.status == "not-run" {
        return String::new();
    }
    if let Some(error) = &case.error {
        return format!(
            "{open}>\n      <error message=\"{}\">{}</error>\n    </testcase>\n",
            escape(case.status),
            escape(error)
        );
    }
    let Some(result) = case.results.get(k) else {
        return String::new();
    };
    let body = result
        .reasons
        .iter()
        .map(|r| escape(r))
        .collect::<Vec<_>>()
        .join("\n");
    match result.verdict {
        "pass" => format!("{open}/>\n"),
        "foil" => format!(
            "{open}>\n      <system-out>departs from the reference, as a foil is expected to:\n{body}</system-out>\n    </testcase>\n"
        ),
        "fail" | "flaky" => format!(
            "{open}>\n      <failure message=\"{}\">{body}</failure>\n    </testcase>\n",
            escape(result.reasons.first().map_or("failed", |r| r.as_str()))
        ),
        "unsupported" => format!("{open}>\n      <skipped message=\"{body}\"/>\n    </testcase>\n"),
        _ => format!("{open}>\n      <error message=\"{body}\">{body}</error>\n    </testcase>\n"),
    }
}
