//! `junit.xml`: one testcase per case × rasterizer, for CI systems that
//! read JUnit. Failures carry the reasons; unsupported cases are skipped;
//! unreadable cases and broken rasterizers are errors. A foil's departures
//! are reported as passing testcases with the departure in `system-out`,
//! since they are expected. A flaky result (`run --repeat`) is a failure
//! whose message starts `flaky: `.

use super::escape::escape;
use super::json::Report;

pub fn render(report: &Report) -> String {
    let mut xml = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
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
    let tests: usize = report.cases.iter().map(|c| c.results.len().max(1)).sum();
    xml.push_str(&format!(
        "<testsuites name=\"rastercheck\" tests=\"{tests}\" failures=\"{failures}\" errors=\"{errors}\">\n"
    ));
    for (k, rasterizer) in report.rasterizers.iter().enumerate() {
        let tally = &t.verdicts[k].tally;
        let suite_tests = report
            .cases
            .iter()
            .filter(|c| c.status != "not-run")
            .count();
        xml.push_str(&format!(
            "  <testsuite name=\"{}\" tests=\"{suite_tests}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\">\n",
            escape(&rasterizer.name),
            tally.fail + tally.flaky,
            tally.error + t.unreadable + t.reference_failed + t.limit_exceeded,
            tally.unsupported
        ));
        for case in &report.cases {
            let classname = format!("{}.{}", escape(&rasterizer.name), escape(&case.family));
            let time = case.results.get(k).map_or(0.0, |r| r.time_ms / 1000.0);
            let open = format!(
                "    <testcase name=\"{}\" classname=\"{classname}\" time=\"{time:.6}\"",
                escape(&case.id)
            );
            if case.status == "not-run" {
                continue;
            }
            if let Some(error) = &case.error {
                xml.push_str(&format!(
                    "{open}>\n      <error message=\"{}\">{}</error>\n    </testcase>\n",
                    escape(case.status),
                    escape(error)
                ));
                continue;
            }
            let Some(result) = case.results.get(k) else {
                continue;
            };
            let body = result
                .reasons
                .iter()
                .map(|r| escape(r))
                .collect::<Vec<_>>()
                .join("\n");
            match result.verdict {
                "pass" => xml.push_str(&format!("{open}/>\n")),
                "foil" => xml.push_str(&format!(
                    "{open}>\n      <system-out>departs from the reference, as a foil is expected to:\n{body}</system-out>\n    </testcase>\n"
                )),
                "fail" | "flaky" => xml.push_str(&format!(
                    "{open}>\n      <failure message=\"{}\">{body}</failure>\n    </testcase>\n",
                    escape(result.reasons.first().map_or("failed", |r| r.as_str()))
                )),
                "unsupported" => xml.push_str(&format!("{open}>\n      <skipped message=\"{body}\"/>\n    </testcase>\n")),
                _ => xml.push_str(&format!("{open}>\n      <error message=\"{body}\">{body}</error>\n    </testcase>\n")),
            }
        }
        xml.push_str("  </testsuite>\n");
    }
    xml.push_str("</testsuites>\n");
    xml
}
