// The registry (formats.cpp) as the help texts and tables say it: `ridt formats`, the README's
// table and docs/cli.md's (which the tests compare with `ridt formats --markdown`).
#include "formats.hpp"

namespace ridt::io {
namespace {

using namespace detail;

// Formats that hold the same in a role, one line of a table.
struct Line {
  std::vector<std::string> extensions;
  std::string holds;
};

// A role: its names, and its lines in the registry's order.
struct Section {
  const char* title;
  const char* commands;
  std::vector<Line> lines;
};

template <class Fn>
Section section_of(const RoleName<Fn>& role) {
  Section s{role.title, role.commands, {}};
  for (const Format& f : formats()) {
    const Role<Fn>& r = f.*role.role;
    if (!r.fn) continue;
    std::string holds(r.holds);
    if (r.through_gdal) holds += " (through GDAL)";
    const std::string ext = !f.extension.empty() ? std::string(f.extension) : role.any_extension ? "any other" : "none";
    if (!s.lines.empty() && s.lines.back().holds == holds)
      s.lines.back().extensions.push_back(ext);
    else
      s.lines.push_back({{ext}, holds});
  }
  return s;
}

std::vector<Section> sections() {
  return {section_of(kPointsIn),   section_of(kPointsOut), section_of(kTrianglesIn), section_of(kTriangulationOut),
          section_of(kVoronoiOut), section_of(kValuesOut), section_of(kGraphIn),     section_of(kSizeIn),
          section_of(kMeshFiles),  section_of(kTerrainIn), section_of(kTinOut),      section_of(kDemOut)};
}

std::string joined(const std::vector<std::string>& items, bool code, const char* between) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const bool word = items[i] == "any other" || items[i] == "none";
    out += (i == 0 ? "" : between) + (code && !word ? "`" + items[i] + "`" : items[i]);
  }
  return out;
}

std::string markdown(const std::vector<Section>& all, bool summary) {
  std::string out = summary ? "| role | commands | extensions |\n|---|---|---|\n"
                            : "| role (commands) | extension | what the file holds |\n|---|---|---|\n";
  for (const Section& s : all) {
    if (summary) {
      std::vector<std::string> every;
      for (const Line& l : s.lines) every.insert(every.end(), l.extensions.begin(), l.extensions.end());
      out += std::string("| ") + s.title + " | " + s.commands + " | " + joined(every, true, ", ") + " |\n";
      continue;
    }
    for (std::size_t i = 0; i < s.lines.size(); ++i)
      out += "| " + (i == 0 ? std::string(s.title) + " (" + s.commands + ")" : std::string()) + " | " +
          joined(s.lines[i].extensions, true, ", ") + " | " + s.lines[i].holds + " |\n";
  }
  return out;
}

std::string plain(const std::vector<Section>& all) {
  std::string out;
  for (const Section& s : all) {
    out += std::string(s.title) + " (" + s.commands + ")\n";
    for (const Line& l : s.lines) {
      std::string ext = joined(l.extensions, false, " ");
      ext.resize(std::max<std::size_t>(ext.size(), 22), ' ');
      out += "  " + ext + "  " + l.holds + "\n";
    }
  }
  return out;
}

}  // namespace

std::string point_formats() { return extensions_with(kPointsIn); }
std::string point_output_formats() { return extensions_with(kPointsOut); }
std::string triangle_formats() { return extensions_with(kTrianglesIn); }
std::string triangulation_formats() { return extensions_with(kTriangulationOut); }
std::string voronoi_formats() { return extensions_with(kVoronoiOut); }
std::string values_formats() { return extensions_with(kValuesOut); }

std::string formats_table(bool as_markdown, bool summary) {
  return as_markdown || summary ? markdown(sections(), summary) : plain(sections());
}

}  // namespace ridt::io
