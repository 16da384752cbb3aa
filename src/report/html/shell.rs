//! What every page shares: its head, with the style sheet and the script
//! that records, for the browser test, what loaded.

use std::fmt::Write as _;

use crate::report::escape::escape;

pub(super) const STYLE: &str = r#"
:root { --fg:#1d2330; --muted:#667085; --line:#d9dee7; --bg:#f6f7f9; --card:#fff;
  --pass:#1a7f37; --fail:#c62828; --foil:#8250df; --unsupported:#9a6700; --error:#b42318; }
* { box-sizing: border-box; }
body { margin:0; font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif; color:var(--fg); background:var(--bg); }
main { max-width:1760px; margin:0 auto; padding:20px 28px 60px; }
h1 { font-size:24px; margin:0 0 4px; } h2 { font-size:20px; margin:32px 0 10px; border-bottom:2px solid var(--line); padding-bottom:4px; }
h3 { font-size:16px; margin:0; } h4 { font-size:13px; margin:14px 0 6px; text-transform:uppercase; letter-spacing:.04em; color:var(--muted); }
code, pre { font:12.5px/1.4 ui-monospace,SFMono-Regular,Menlo,Consolas,monospace; }
pre { background:#f1f3f6; border:1px solid var(--line); border-radius:6px; padding:8px 10px; overflow:auto; max-height:420px; white-space:pre-wrap; word-break:break-word; }
a { color:#0b62c4; text-decoration:none; } a:hover { text-decoration:underline; }
.muted { color:var(--muted); }
.banner { background:#fff4e5; border:1px solid #f0b35a; border-radius:6px; padding:8px 12px; margin:10px 0; }
.summary { display:flex; flex-wrap:wrap; gap:16px; align-items:flex-start; margin-top:14px; }
.panel { background:var(--card); border:1px solid var(--line); border-radius:8px; padding:12px 14px; }
table { border-collapse:collapse; background:var(--card); }
th, td { border:1px solid var(--line); padding:4px 8px; text-align:left; vertical-align:top; }
th { background:#eef1f5; font-weight:600; }
td.n, th.n { text-align:right; font-variant-numeric:tabular-nums; }
table.cases { width:100%; } table.cases td { font-size:13px; }
table.cases td.id { font-family:ui-monospace,Menlo,Consolas,monospace; font-size:12.5px; white-space:nowrap; }
.badge { display:inline-block; min-width:44px; text-align:center; font-size:11px; font-weight:700; letter-spacing:.03em; color:#fff; border-radius:4px; padding:1px 6px; margin-right:6px; }
.pass { background:var(--pass); } .fail { background:var(--fail); } .foil { background:var(--foil); }
.unsupported { background:var(--unsupported); } .error, .flaky, .unreadable, .reference-failed, .limit-exceeded, .differ { background:var(--error); }
.not-run, .missing { background:#8c959f; } .match { background:var(--pass); }
.metric { color:var(--muted); font-size:12px; }
.card { background:var(--card); border:1px solid var(--line); border-left:5px solid var(--line); border-radius:8px; padding:14px 16px; margin:16px 0; }
.card.k-fail, .card.k-error, .card.k-flaky, .card.k-problem { border-left-color:var(--fail); }
.card.k-foil { border-left-color:var(--foil); } .card.k-pass { border-left-color:var(--pass); }
.card header { display:flex; flex-wrap:wrap; align-items:baseline; gap:8px 12px; }
.card header .id { font-family:ui-monospace,Menlo,Consolas,monospace; font-size:15px; font-weight:600; }
.reasons { margin:8px 0; padding-left:20px; color:#7a1c1c; }
.pictures { display:flex; gap:14px; padding-bottom:6px; align-items:flex-start; }
.pictures figure { flex:0 1 auto; min-width:0; }
.pictures.stack { flex-direction:column; overflow-x:auto; }
.pictures.stack figure { flex:none; } .pictures.stack img { max-width:none; }
.pictures.tall { max-height:640px; overflow-y:auto; } .pictures.tall figure { flex:none; }
.pictures.heat { flex-wrap:wrap; }
figure { margin:0; } figcaption { font-size:12px; color:var(--muted); margin-top:3px; }
figure img { display:block; image-rendering:pixelated; border:1px solid #000; max-width:100%; height:auto; }
.key { display:flex; flex-wrap:wrap; gap:4px 14px; font-size:12px; margin:8px 0 2px; color:var(--fg); }
.key span { white-space:nowrap; } .key i { display:inline-block; width:12px; height:12px; border:1px solid #555; vertical-align:-2px; margin-right:4px; }
.metrics { display:flex; flex-wrap:wrap; gap:14px; align-items:flex-start; }
.ramp { display:inline-block; width:140px; height:12px; border:1px solid #555; vertical-align:-2px; margin:0 4px; }
details { margin-top:8px; } summary { cursor:pointer; color:#0b62c4; }
.files { font-size:12px; }
.scroll { max-height:460px; overflow:auto; border:1px solid var(--line); border-radius:6px; }
table.failures td:nth-child(2) { white-space:nowrap; }
.plots { display:flex; flex-wrap:wrap; gap:16px; }
.plots figure.plot { background:var(--card); border:1px solid var(--line); border-radius:8px; padding:8px; max-width:700px; }
.plots figure.plot img { border:none; image-rendering:auto; }
"#;

/// After load, records on `<body>` for the browser test: the pictures that
/// decoded of all (`data-images`), the script errors seen
/// (`data-errors`), and the milliseconds from navigation to load
/// (`data-load-ms`).
const SCRIPT: &str = r#"var rastercheckErrors = 0;
window.addEventListener('error', function () { rastercheckErrors++; }, true);
window.addEventListener('load', function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; i++) { if (imgs[i].complete && imgs[i].naturalWidth > 0) ok++; }
  document.body.dataset.images = ok + '/' + imgs.length;
  document.body.dataset.errors = rastercheckErrors;
  document.body.dataset.loadMs = Math.round(performance.now());
});"#;

/// A page's opening, up to `<main>`: its title, and a `<base>` when its
/// links are relative to another folder.
pub(super) fn head(title: &str, base: Option<&str>) -> String {
    let mut html = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    if let Some(base) = base {
        let _ = writeln!(html, "<base href=\"{}\">", escape(base));
    }
    let _ = write!(html, "<title>{}</title>\n<style>", escape(title));
    html.push_str(STYLE);
    html.push_str("</style>\n<script>");
    html.push_str(SCRIPT);
    html.push_str("</script></head>\n<body><main>\n");
    html
}
