// histogram_svg(): a self-contained SVG bar chart of one Histogram. Bins are
// drawn with equal widths (the aspect-ratio bins are not uniform; the axis
// labels give the true edges). Deterministic output, locale independent.
#include <algorithm>
#include <cstdint>
#include <string>

#include "pqmesh/quality.hpp"
#include "quality/format.hpp"

namespace pqmesh {
namespace {

using detail::format_fixed;
using detail::format_general;

constexpr double kWidth = 720, kHeight = 400;
constexpr double kLeft = 70, kRight = 20, kTop = 50, kBottom = 60;

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string num(double v) { return format_fixed(v, 2); }

// Appends the pieces in order. (Used instead of chains of "literal" + string,
// which trip a GCC 12 -Wrestrict false positive.)
template <class... Parts>
void append(std::string& s, const Parts&... parts) {
  ((s += parts), ...);
}

void append_text(std::string& s, double x, double y, const char* anchor, int size, const std::string& body) {
  append(s, "<text x=\"", num(x), "\" y=\"", num(y), "\" text-anchor=\"", anchor, "\" font-size=\"",
         std::to_string(size), "\">", xml_escape(body), "</text>\n");
}

}  // namespace

std::string histogram_svg(const Histogram& h, const std::string& title) {
  const std::size_t bins = h.counts.size();
  const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  std::int64_t peak = 0;
  std::int64_t total = 0;
  for (std::int64_t c : h.counts) {
    peak = std::max(peak, c);
    total += c;
  }
  std::string s;
  append(s, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"", num(kWidth), "\" height=\"", num(kHeight),
         "\" viewBox=\"0 0 ", num(kWidth), " ", num(kHeight), "\" font-family=\"sans-serif\">\n");
  append(s, "<title>", xml_escape(title), "</title>\n");
  append(s, "<rect x=\"0\" y=\"0\" width=\"", num(kWidth), "\" height=\"", num(kHeight), "\" fill=\"white\"/>\n");
  append_text(s, kWidth / 2, 28, "middle", 16, title);
  // Axes.
  append(s, "<path d=\"M", num(kLeft), " ", num(kTop), " V", num(kTop + plot_h), " H", num(kLeft + plot_w),
         "\" fill=\"none\" stroke=\"black\"/>\n");
  // Y ticks at 0, 1/4, ..., 1 of the peak count (integers; duplicates skipped).
  std::int64_t previous = -1;
  for (int k = 0; k <= 4; ++k) {
    const std::int64_t value = peak * k / 4;
    if (value == previous) continue;
    previous = value;
    const double y =
        kTop + plot_h - (peak == 0 ? 0.0 : plot_h * static_cast<double>(value) / static_cast<double>(peak));
    append(s, "<path d=\"M", num(kLeft - 5), " ", num(y), " H", num(kLeft), "\" stroke=\"black\"/>\n");
    append_text(s, kLeft - 8, y + 4, "end", 11, std::to_string(value));
  }
  std::string axis_label = h.measure;
  append(axis_label, "  (", std::to_string(total), " elements)");
  append_text(s, kLeft + plot_w / 2, kHeight - 12, "middle", 12, axis_label);
  if (bins == 0) {
    s += "</svg>\n";
    return s;
  }
  // Bars, each with a tooltip giving its exact range and count.
  const double bar_w = plot_w / static_cast<double>(bins);
  for (std::size_t i = 0; i < bins; ++i) {
    const double x = kLeft + bar_w * static_cast<double>(i);
    const double bh = peak == 0 ? 0.0 : plot_h * static_cast<double>(h.counts[i]) / static_cast<double>(peak);
    std::string tip;
    append(tip, "[", format_general(h.edges[i], 6), ", ", format_general(h.edges[i + 1], 6), "): ",
           std::to_string(h.counts[i]));
    append(s, "<rect x=\"", num(x + 1), "\" y=\"", num(kTop + plot_h - bh), "\" width=\"",
           num(std::max(bar_w - 2, 0.5)), "\" height=\"", num(bh), "\" fill=\"#4682b4\"><title>",
           xml_escape(tip), "</title></rect>\n");
  }
  // X labels at bin edges; at most ~19 labels so they do not collide.
  const std::size_t step = std::max<std::size_t>(1, (bins + 17) / 18);
  for (std::size_t i = 0; i <= bins; i += step) {
    const double x = kLeft + bar_w * static_cast<double>(i);
    append(s, "<path d=\"M", num(x), " ", num(kTop + plot_h), " V", num(kTop + plot_h + 5),
           "\" stroke=\"black\"/>\n");
    append_text(s, x, kTop + plot_h + 18, "middle", 11, format_general(h.edges[i], 4));
  }
  s += "</svg>\n";
  return s;
}

}  // namespace pqmesh
