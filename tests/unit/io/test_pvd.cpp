//! @file ParaView series: every listed file exists and opens at its time; restarts continue it.
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <vtkDataObject.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUtilities.h>

#include "hvi/common/error.hpp"
#include "hvi/io/output.hpp"
#include "test_support.hpp"

namespace hvi::io::test {
namespace {
namespace fs = std::filesystem;

struct PvdEntry {
  double time;
  int part;
  std::string file;
};

//! Parses the .pvd with VTK's XML parser (expat), as ParaView's reader does.
std::vector<PvdEntry> parsePvd(const fs::path& pvd) {
  vtkSmartPointer<vtkXMLDataElement> root;
  root.TakeReference(vtkXMLUtilities::ReadElementFromFile(pvd.c_str()));
  std::vector<PvdEntry> out;
  if (!root) {
    ADD_FAILURE() << pvd << " is not well-formed XML";
    return out;
  }
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* c = root->FindNestedElementWithName("Collection");
  if (!c) {
    ADD_FAILURE() << "no Collection";
    return out;
  }
  for (int i = 0; i < c->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* d = c->GetNestedElement(i);
    PvdEntry e{0.0, -1, d->GetAttribute("file") ? d->GetAttribute("file") : ""};
    // strtod, not VTK's scalar parser, so the check is on the exact text written.
    e.time = std::strtod(d->GetAttribute("timestep"), nullptr);
    d->GetScalarAttribute("part", e.part);
    out.push_back(e);
  }
  return out;
}

//! Opens a listed file with the reader its extension calls for and returns its TIME.
double loadTime(const fs::path& file) {
  vtkDataObject* data = nullptr;
  vtkNew<vtkXMLUnstructuredGridReader> u;
  vtkNew<vtkXMLImageDataReader> i;
  vtkNew<vtkXMLPolyDataReader> p;
  const std::string ext = file.extension().string();
  vtkXMLReader* r = ext == ".vtu" ? static_cast<vtkXMLReader*>(u) :
                    ext == ".vti" ? static_cast<vtkXMLReader*>(i) : static_cast<vtkXMLReader*>(p);
  EXPECT_TRUE(r->CanReadFile(file.c_str())) << file;
  r->SetFileName(file.c_str());
  r->Update();
  data = r->GetOutputDataObject(0);
  vtkDataArray* t = data ? data->GetFieldData()->GetArray("TIME") : nullptr;
  if (!t) {
    ADD_FAILURE() << file << " has no TIME";
    return -1.0;
  }
  return t->GetTuple1(0);
}

TEST(Pvd, SeriesListsEveryPartAndEachOpensAtItsTime) {
  ScratchDir dir;
  PvdSeries series(dir / "tvd.pvd");
  const double times[] = {0.0, 0.3, 0.1 + 0.2 + 1.0};  // the last needs 17 digits
  for (int n = 0; n < 3; ++n) {
    const auto files = writeVtk(dir / fmt::format("tvd_{:04d}", n), gridSnapshot(6, 5, times[n], n));
    series.add(times[n], files);  // absolute paths inside the folder become relative
    ASSERT_EQ(parsePvd(dir / "tvd.pvd").size(), 2u * (n + 1)) << "valid after every add";
  }
  const auto entries = parsePvd(dir / "tvd.pvd");
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const PvdEntry& e = entries[k];
    EXPECT_EQ(e.time, times[k / 2]);
    EXPECT_EQ(e.part, static_cast<int>(k % 2));
    EXPECT_EQ(e.file, fmt::format("tvd_{:04d}{}", k / 2, k % 2 ? "_markers.vtp" : ".vti"));
    ASSERT_TRUE(fs::exists(dir / e.file)) << e.file;
    EXPECT_EQ(loadTime(dir / e.file), e.time);
  }
  EXPECT_EQ(dir.entries().size(), 7u);  // 6 data files + the .pvd, no temporaries
}

TEST(Pvd, ParticleSeriesOpens) {
  ScratchDir dir;
  PvdSeries series(dir / "sph.pvd");
  series.add(0.5, writeVtk(dir / "sph_0000", particleSnapshot(10, 0.5)));
  const auto entries = parsePvd(dir / "sph.pvd");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(loadTime(dir / entries[0].file), 0.5);
}

TEST(Pvd, ResumeKeepsEntriesUpToTheRestartTimeAndContinues) {
  ScratchDir dir;
  {
    PvdSeries first(dir / "run.pvd");
    for (int n = 0; n < 4; ++n) first.add(n, {fmt::format("s{}.vti", n), fmt::format("s{}_markers.vtp", n)});
  }
  PvdSeries restarted(dir / "run.pvd");
  restarted.resumeFrom(1.5);
  auto entries = parsePvd(dir / "run.pvd");  // rewritten at once: no stale later entries
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries.back().time, 1.0);
  restarted.add(2.0, {"r2.vti"});
  restarted.add(2.0, {"r2.vti"});  // the same file again replaces, not duplicates
  restarted.add(2.0, {"r2_markers.vtp"});  // another file at that time is the next part
  entries = parsePvd(dir / "run.pvd");
  ASSERT_EQ(entries.size(), 6u);
  EXPECT_EQ(entries[3].file, "s1_markers.vtp");
  EXPECT_EQ(entries[4].file, "r2.vti");
  EXPECT_EQ(entries[4].part, 0);
  EXPECT_EQ(entries[5].file, "r2_markers.vtp");
  EXPECT_EQ(entries[5].part, 1);
}

TEST(Pvd, ResumeWithExactTimesAndEscapedNames) {
  ScratchDir dir;
  const double t = 0.1 + 0.2;  // 0.30000000000000004: must survive the text round trip
  {
    PvdSeries s(dir / "x.pvd");
    s.add(t, {"a&b <\"c\">.vtu"});
    s.add(std::nextafter(t, 1.0), {"later.vtu"});
  }
  PvdSeries s(dir / "x.pvd");
  s.resumeFrom(t);
  const auto entries = parsePvd(dir / "x.pvd");
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].file, "a&b <\"c\">.vtu");
  EXPECT_EQ(entries[0].time, t);
}

TEST(Pvd, ResumeWithoutFileStartsFreshAndGarbageIsAnInputError) {
  ScratchDir dir;
  PvdSeries fresh(dir / "none.pvd");
  EXPECT_NO_THROW(fresh.resumeFrom(10.0));
  std::ofstream(dir / "bad.pvd") << "this is not xml <";
  PvdSeries bad(dir / "bad.pvd");
  EXPECT_THROW(bad.resumeFrom(1.0), InputError);
  std::ofstream(dir / "other.pvd") << "<VTKFile type=\"ImageData\"></VTKFile>";
  PvdSeries other(dir / "other.pvd");
  EXPECT_THROW(other.resumeFrom(1.0), InputError);
}

}  // namespace
}  // namespace hvi::io::test
