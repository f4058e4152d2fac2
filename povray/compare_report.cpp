#include "compare_report.h"

#include <fmt/core.h>

#include <cmath>

namespace lucent {

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20) out += fmt::format("\\u{:04x}", c);
        else out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

namespace {

// JSON has no infinity: an infinite PSNR (identical images) is null.
std::string jsonNumber(double v) { return std::isfinite(v) ? fmt::format("{}", v) : "null"; }

std::string html(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string psnrText(double psnr) {
  return std::isfinite(psnr) ? fmt::format("{:.2f} dB", psnr) : "∞ (identical)";
}

}  // namespace

std::string reportJson(const CompareReport& r) {
  const ImageMetrics& m = r.metrics;
  std::string warnings;
  for (size_t i = 0; i < r.warnings.size(); ++i)
    warnings += fmt::format("{}    {}", i == 0 ? "\n" : ",\n", jsonString(r.warnings[i]));
  if (!r.warnings.empty()) warnings += "\n  ";
  return fmt::format(
      "{{\n"
      "  \"scene\": {},\n"
      "  \"pov_scene\": {},\n"
      "  \"pov_scene_hand_written\": {},\n"
      "  \"width\": {},\n"
      "  \"height\": {},\n"
      "  \"samples\": {},\n"
      "  \"max_depth\": {},\n"
      "  \"min_weight\": {},\n"
      "  \"metrics_space\": \"sRGB-encoded values in [0,1] of the 16-bit linear renders\",\n"
      "  \"psnr_db\": {},\n"
      "  \"ssim\": {},\n"
      "  \"rmse\": {},\n"
      "  \"max_diff\": {},\n"
      "  \"max_diff_x\": {},\n"
      "  \"max_diff_y\": {},\n"
      "  \"threshold\": {},\n"
      "  \"pixels_over_threshold\": {},\n"
      "  \"share_over_threshold\": {},\n"
      "  \"lucent_render\": {},\n"
      "  \"lucent_seconds\": {},\n"
      "  \"povray_seconds\": {},\n"
      "  \"povray_command\": {},\n"
      "  \"images\": {{\n"
      "    \"lucent\": {},\n"
      "    \"povray\": {},\n"
      "    \"lucent_linear16\": {},\n"
      "    \"povray_linear16\": {},\n"
      "    \"heat_map\": {},\n"
      "    \"heat_map_full_scale\": {},\n"
      "    \"povray_log\": {}\n"
      "  }},\n"
      "  \"warnings\": [{}]\n"
      "}}\n",
      jsonString(r.scene), jsonString(r.povScene), r.handWritten ? "true" : "false", r.width,
      r.height, r.samples, r.maxDepth, jsonNumber(r.minWeight), jsonNumber(m.psnr),
      jsonNumber(m.ssim), jsonNumber(m.rmse), jsonNumber(m.maxDiff), m.maxX, m.maxY,
      jsonNumber(m.threshold), m.pixelsOver, jsonNumber(m.shareOver), jsonString(r.lucentRender),
      jsonNumber(r.lucentSeconds), jsonNumber(r.povraySeconds), jsonString(r.povrayCommand),
      jsonString(r.lucentImage), jsonString(r.povrayImage), jsonString(r.lucentLinear),
      jsonString(r.povrayLinear), jsonString(r.heatMap), jsonNumber(r.heatMapScale),
      jsonString(r.povrayLog), warnings);
}

std::string reportHtml(const CompareReport& r) {
  const ImageMetrics& m = r.metrics;
  std::string warnings;
  for (const std::string& w : r.warnings) warnings += "<li>" + html(w) + "</li>\n";
  if (warnings.empty()) warnings = "<li>none</li>\n";
  return fmt::format(
      R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>Lucent vs POV-Ray: {scene}</title>
<style>
body {{ font-family: sans-serif; margin: 1.5em; color: #222; }}
.images {{ display: flex; gap: 1em; flex-wrap: wrap; }}
figure {{ margin: 0; }}
figure img {{ image-rendering: pixelated; width: {shown}px; border: 1px solid #999; }}
figcaption {{ text-align: center; margin-top: .3em; }}
table {{ border-collapse: collapse; margin-top: 1em; }}
td, th {{ border: 1px solid #bbb; padding: .25em .7em; text-align: left; }}
code {{ font-size: 90%; }}
</style>
</head>
<body>
<h1>Lucent vs POV-Ray</h1>
<p>Scene <code>{scene}</code>, POV-Ray file <code>{pov}</code>{hand}; {w}&times;{h} pixels,
{samples} sample(s) per pixel, max depth {depth}, min weight {weight}.</p>
<div class="images">
<figure><img src="{limg}" alt="Lucent render"><figcaption>Lucent ({lsec:.3f} s)</figcaption></figure>
<figure><img src="{pimg}" alt="POV-Ray render"><figcaption>POV-Ray ({psec:.3f} s)</figcaption></figure>
<figure><img src="{heat}" alt="difference heat map"><figcaption>Difference (black: none, brightest: &ge; {scale:.4f})</figcaption></figure>
</div>
<table>
<tr><th>PSNR</th><td>{psnr}</td></tr>
<tr><th>SSIM (luminance)</th><td>{ssim:.6f}</td></tr>
<tr><th>RMSE</th><td>{rmse:.6g}</td></tr>
<tr><th>Maximum difference</th><td>{maxd:.6g} at ({mx}, {my})</td></tr>
<tr><th>Pixels off by more than {thr:.4f} (2/255)</th><td>{over} ({share:.3f} %)</td></tr>
<tr><th>Lucent time</th><td>{lsec:.3f} s ({how})</td></tr>
<tr><th>POV-Ray time</th><td>{psec:.3f} s</td></tr>
</table>
<p>Metrics compare sRGB-encoded values in [0, 1] of the two 16-bit linear renders
(<a href="{llin}">{llin}</a>, <a href="{plin}">{plin}</a>). POV-Ray command:<br><code>{cmd}</code>
(<a href="{log}">log</a>)</p>
<h2>Warnings</h2>
<ul>
{warnings}</ul>
</body>
</html>
)",
      fmt::arg("scene", html(r.scene)), fmt::arg("pov", html(r.povScene)),
      fmt::arg("hand", r.handWritten ? " (hand-written)" : " (exported)"), fmt::arg("w", r.width),
      fmt::arg("h", r.height), fmt::arg("samples", r.samples), fmt::arg("depth", r.maxDepth),
      fmt::arg("weight", r.minWeight), fmt::arg("shown", std::max(256, std::min(480, r.width))),
      fmt::arg("limg", html(r.lucentImage)), fmt::arg("pimg", html(r.povrayImage)),
      fmt::arg("heat", html(r.heatMap)), fmt::arg("lsec", r.lucentSeconds),
      fmt::arg("psec", r.povraySeconds), fmt::arg("scale", r.heatMapScale),
      fmt::arg("psnr", psnrText(m.psnr)), fmt::arg("ssim", m.ssim), fmt::arg("rmse", m.rmse),
      fmt::arg("maxd", m.maxDiff), fmt::arg("mx", m.maxX), fmt::arg("my", m.maxY),
      fmt::arg("thr", m.threshold), fmt::arg("over", m.pixelsOver),
      fmt::arg("share", 100.0 * m.shareOver), fmt::arg("how", html(r.lucentRender)),
      fmt::arg("llin", html(r.lucentLinear)), fmt::arg("plin", html(r.povrayLinear)),
      fmt::arg("cmd", html(r.povrayCommand)), fmt::arg("log", html(r.povrayLog)),
      fmt::arg("warnings", warnings));
}

}  // namespace lucent
