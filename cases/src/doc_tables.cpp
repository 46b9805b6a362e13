//! @file Markdown tables for docs/scenes.md, columns padded to their widest cell.
#include "hvi/cases/doc_tables.hpp"

#include <algorithm>
#include <vector>

#include "detail/keys.hpp"
#include "hvi/cases/effects.hpp"

namespace hvi::cases {
namespace {

using Row = std::vector<std::string>;

std::string markdownTable(const Row& header, const std::vector<Row>& rows) {
  std::vector<std::size_t> width(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    width[c] = header[c].size();
    for (const Row& r : rows) width[c] = std::max(width[c], r[c].size());
  }
  auto line = [&](const Row& r) {
    std::string s = "|";
    for (std::size_t c = 0; c < r.size(); ++c)
      s += " " + r[c] + std::string(width[c] - r[c].size(), ' ') + " |";
    return s + "\n";
  };
  std::string out = line(header) + "|";
  for (std::size_t w : width) out += std::string(w + 2, '-') + "|";
  out += "\n";
  for (const Row& r : rows) out += line(r);
  return out;
}

// Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "`" + std::string(s) + "`".
std::string code(std::string_view s) {
  std::string out(1, '`');
  out.append(s).push_back('`');
  return out;
}

template <class S>
void addKeys(std::vector<Row>& rows, const std::string& prefix,
             std::span<const detail::KeyRow<S>> keys) {
  for (const auto& k : keys)
    if (k.kind != detail::ValueKind::Section)  // a section has its own table
        rows.push_back({code(prefix + std::string(k.key)), std::string(k.docValue),
                      std::string(k.docDefault)});
}

}  // namespace

std::string effectTableMarkdown() {
  std::vector<Row> rows;
  for (const EffectInfo& e : effectTable()) {
    Row r{code(e.name), std::string(e.meaning)};
    for (SolverKind s : {SolverKind::Sph, SolverKind::Tvd, SolverKind::Riemann})
      r.push_back(supports(s, e.effect) ? "yes" : "");
    rows.push_back(std::move(r));
  }
  return markdownTable({"effect", "meaning", "sph", "tvd", "riemann"}, rows);
}

std::string keyTableMarkdown(std::initializer_list<std::string_view> sections) {
  std::vector<Row> rows;
  for (std::string_view sec : sections) {
    const std::string prefix = sections.size() > 1 ? std::string(sec) + "." : "";
    if (sec == "root") addKeys(rows, prefix, detail::rootKeys());
    if (sec == "time") addKeys(rows, prefix, detail::timeKeys());
    if (sec == "domain") addKeys(rows, prefix, detail::domainKeys());
    if (sec == "materials") addKeys(rows, prefix, detail::materialKeys());
    if (sec == "materials.tillotson") addKeys(rows, prefix, detail::tillotsonKeys());
    if (sec == "materials.ideal_gas") addKeys(rows, prefix, detail::idealGasKeys());
    if (sec == "materials.mie_gruneisen") addKeys(rows, prefix, detail::mieGruneisenKeys());
    if (sec == "materials.strength") {
      addKeys(rows, prefix, detail::strengthKeys());
      addKeys(rows, prefix, detail::damageKeys());
    }
    if (sec == "bodies") addKeys(rows, prefix, detail::bodyKeys());
    if (sec == "sph") addKeys(rows, prefix, detail::sphKeys());
    if (sec == "tvd") addKeys(rows, prefix, detail::tvdKeys());
    if (sec == "riemann") addKeys(rows, prefix, detail::riemannKeys());
    if (sec == "output") addKeys(rows, prefix, detail::outputKeys());
  }
  return markdownTable({"key", "value", "default"}, rows);
}

}  // namespace hvi::cases
