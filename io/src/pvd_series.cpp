//! @file ParaView .pvd time series, rewritten atomically after every snapshot.
#include <algorithm>

#include <fmt/format.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include "hvi/common/atomic_file.hpp"
#include "hvi/common/error.hpp"
#include "hvi/io/output.hpp"

namespace hvi::io {
namespace fs = std::filesystem;

namespace {

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

//! Relative to the .pvd's folder when the file lies inside it, so that a run folder can be
//! moved or copied and still open.
std::string entryPath(const fs::path& pvd, const fs::path& file) {
  if (!file.is_absolute()) return file.generic_string();
  const fs::path dir = fs::absolute(pvd).lexically_normal().parent_path();
  const fs::path rel = file.lexically_normal().lexically_relative(dir);
  if (rel.empty() || *rel.begin() == "..") return file.generic_string();
  return rel.generic_string();
}

}  // namespace

PvdSeries::PvdSeries(fs::path file) : file_(std::move(file)) {}

void PvdSeries::add(double time, const std::vector<fs::path>& files) {
  for (const fs::path& f : files) {
    const std::string path = entryPath(file_, f);
    // Re-adding a file at a time already listed (a restart writing its first snapshot again)
    // replaces that entry; another file at that time becomes the next part.
    auto same = std::find_if(entries_.begin(), entries_.end(),
                             [&](const Entry& e) { return e.time == time && e.file == path; });
    if (same != entries_.end()) continue;
    int part = 0;
    for (const Entry& e : entries_)
      if (e.time == time) part = std::max(part, e.part + 1);
    entries_.push_back({time, part, path});
  }
  std::stable_sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.time < b.time || (a.time == b.time && a.part < b.part);
  });
  write();
}

void PvdSeries::resumeFrom(double upTo) {
  entries_.clear();
  std::error_code ec;
  if (!fs::exists(file_, ec)) return;  // a run that wrote no series yet starts a fresh one
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(file_.c_str()));
  const std::string name = file_.string();
  if (!root || std::string(root->GetName()) != "VTKFile" ||
      std::string(root->GetAttribute("type") ? root->GetAttribute("type") : "") != "Collection")
    throw InputError(fmt::format("{} is not a ParaView collection (.pvd) file; remove it or "
                                 "choose another output folder", name));
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (!collection) throw InputError(fmt::format("{}: <Collection> element is missing", name));
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* ds = collection->GetNestedElement(i);
    if (std::string(ds->GetName()) != "DataSet") continue;
    double time = 0.0;
    int part = 0;
    const char* file = ds->GetAttribute("file");
    if (!ds->GetScalarAttribute("timestep", time) || !file)
      throw InputError(fmt::format("{}: DataSet entry {} lacks timestep or file", name, i));
    if (!ds->GetScalarAttribute("part", part)) part = 0;
    if (time <= upTo) entries_.push_back({time, part, file});
  }
  std::stable_sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) {
    return a.time < b.time || (a.time == b.time && a.part < b.part);
  });
  write();
}

void PvdSeries::write() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_)
    // {} prints the shortest decimal that reads back as the same double.
    xml += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"{}\" file=\"{}\"/>\n",
                       e.time, e.part, xmlEscape(e.file));
  xml += "  </Collection>\n</VTKFile>\n";
  writeTextAtomically(file_, xml);
}

}  // namespace hvi::io
