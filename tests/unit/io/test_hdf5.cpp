//! @file HDF5 snapshots: exact round trip, layout as documented, readable by h5py, bad files.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "hvi/common/error.hpp"
#include "hvi/io/output.hpp"
#include "test_support.hpp"

namespace hvi::io::test {
namespace {

TEST(Hdf5, ParticleSnapshotRoundTripsBitForBit) {
  ScratchDir dir;
  const Snapshot snap = particleSnapshot(1000);
  writeHdf5(dir / "p.h5", snap, sampleScene());
  std::string scene;
  const Snapshot back = readHdf5(dir / "p.h5", &scene);
  expectBitEqual(snap, back);
  EXPECT_EQ(scene, sampleScene());
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.h5"});
}

TEST(Hdf5, GridSnapshotWithMarkersRoundTripsBitForBit) {
  ScratchDir dir;
  const Snapshot snap = gridSnapshot(37, 23);
  writeHdf5(dir / "g.h5", snap, sampleScene());
  expectBitEqual(snap, readHdf5(dir / "g.h5"));
}

TEST(Hdf5, EmptyParticleSetAndEmptyListsRoundTrip) {
  ScratchDir dir;
  Snapshot snap = particleSnapshot(0);
  snap.materialNames.clear();
  snap.objectNames.clear();
  writeHdf5(dir / "e.h5", snap, "");
  std::string scene = "x";
  expectBitEqual(snap, readHdf5(dir / "e.h5", &scene));
  EXPECT_EQ(scene, "");
}

TEST(Hdf5, FieldOrderIsKeptNotAlphabetical) {
  ScratchDir dir;
  Snapshot snap = gridSnapshot(3, 2);
  std::reverse(snap.fields.begin(), snap.fields.end());  // z..a order would sort differently
  writeHdf5(dir / "o.h5", snap, "");
  const Snapshot back = readHdf5(dir / "o.h5");
  ASSERT_EQ(back.fields.size(), snap.fields.size());
  for (std::size_t i = 0; i < snap.fields.size(); ++i) EXPECT_EQ(back.fields[i].name, snap.fields[i].name);
}

// HDF5 stamps each object with its creation time (1 s resolution) unless told not to: two runs
// giving the same numbers gave files differing in 17 bytes (issue 11). The second write comes
// more than a second after the first, so stamps, if any, differ.
TEST(Hdf5, IdenticalSnapshotsGiveIdenticalFiles) {
  ScratchDir dir;
  for (const Snapshot& snap : {particleSnapshot(50), gridSnapshot(6, 5)}) {
    writeHdf5(dir / "a.h5", snap, sampleScene());
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    writeHdf5(dir / "b.h5", snap, sampleScene());
    std::ifstream a(dir / "a.h5", std::ios::binary), b(dir / "b.h5", std::ios::binary);
    const std::string bytesA{std::istreambuf_iterator<char>(a), {}};
    const std::string bytesB{std::istreambuf_iterator<char>(b), {}};
    ASSERT_FALSE(bytesA.empty());
    ASSERT_EQ(bytesA.size(), bytesB.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < bytesA.size(); ++i) differing += bytesA[i] != bytesB[i];
    EXPECT_EQ(differing, 0u);
  }
}

TEST(Hdf5, OverwritesAnExistingSnapshot) {
  ScratchDir dir;
  writeHdf5(dir / "s.h5", gridSnapshot(4, 4, 1.0), "old");
  const Snapshot second = gridSnapshot(5, 3, 2.0);
  writeHdf5(dir / "s.h5", second, "new");
  std::string scene;
  expectBitEqual(second, readHdf5(dir / "s.h5", &scene));
  EXPECT_EQ(scene, "new");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"s.h5"});
}

TEST(Hdf5, InconsistentSnapshotIsRejectedBeforeWriting) {
  ScratchDir dir;
  Snapshot snap = gridSnapshot(4, 4);
  snap.fields[1].data.pop_back();
  EXPECT_THROW(writeHdf5(dir / "bad.h5", snap, ""), std::invalid_argument);
  snap = gridSnapshot(4, 4);
  snap.fields[2].name = "a/b";
  EXPECT_THROW(writeHdf5(dir / "bad.h5", snap, ""), std::invalid_argument);
  snap = gridSnapshot(4, 4);
  snap.fields[2].name = snap.fields[0].name;
  EXPECT_THROW(writeHdf5(dir / "bad.h5", snap, ""), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

//! The message must name the file and what is wrong, as every InputError does.
void expectInputError(const std::filesystem::path& file, const std::string& needle) {
  try {
    readHdf5(file);
    ADD_FAILURE() << "no exception for " << file;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
  }
}

TEST(Hdf5, ReadingSomethingElseThrowsInputErrorNamingFileAndProblem) {
  ScratchDir dir;
  expectInputError(dir / "missing.h5", "no such");
  std::ofstream(dir / "text.h5") << "[domain]\nx = 1\n";
  expectInputError(dir / "text.h5", "not an HDF5 file");
}

//! h5py is the foreign reader (and, to damage files, the foreign writer) of these tests.
bool havePythonH5py() {
  static const bool have = std::system("/usr/bin/python3 -c 'import h5py' 2>/dev/null") == 0;
  return have;
}

std::string runPython(const std::string& script, const std::filesystem::path& file) {
  const std::string cmd = fmt::format("/usr/bin/python3 -c \"{}\" '{}' 2>&1", script, file.string());
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    EXPECT_EQ(::pclose(p), 0) << out;
  }
  return out;
}

TEST(Hdf5, HdfFilesMissingPartsOfTheLayoutAreNamed) {
  if (!havePythonH5py()) GTEST_SKIP() << "/usr/bin/python3 has no h5py";
  ScratchDir dir;
  for (const char* name : {"unit.h5", "objects.h5", "shape.h5", "version.h5"})
    writeHdf5(dir / name, gridSnapshot(4, 3), "");
  // One interpreter start for all the damage (each start costs about a second on a busy box).
  runPython("import h5py,sys,os; d=sys.argv[1]; F=lambda n: h5py.File(os.path.join(d,n),'a'); "
            "h5py.File(os.path.join(d,'foreign.h5'),'w')['x']=[1.0]; "
            "f=F('unit.h5'); del f['fields/pressure'].attrs['unit']; f.close(); "
            "f=F('objects.h5'); del f['objects']; f.close(); "
            "f=F('shape.h5'); del f['fields/density']; f['fields/density']=[1.0,2.0]; "
            "f['fields/density'].attrs['unit']='g/cm^3'; f.close(); "
            "f=F('version.h5'); f.attrs['format_version']=2; f.close()",
            dir.path());
  expectInputError(dir / "foreign.h5", "'format' is missing");
  expectInputError(dir / "unit.h5", "attribute 'unit' of fields/pressure is missing");
  expectInputError(dir / "objects.h5", "'objects' is missing");
  expectInputError(dir / "shape.h5", "'fields/density' has shape [2], expected [12]");
  expectInputError(dir / "version.h5", "format_version 2");
}

TEST(Hdf5, H5pyReadsTimeFieldsAndNames) {
  if (!havePythonH5py()) GTEST_SKIP() << "/usr/bin/python3 has no h5py";
  ScratchDir dir;
  const Snapshot snap = particleSnapshot(321, 0.1 + 0.2);  // a time with all mantissa bits set
  writeHdf5(dir / "p.h5", snap, sampleScene());
  const std::string out = runPython(
      "import h5py,sys; f=h5py.File(sys.argv[1],'r'); a=f.attrs; "
      "print(a['format'], a['format_version'], '%.17g' % a['time'], a['step'], a['kind'], a['geometry']); "
      "print(len(f['fields/density']), f['fields/velocity'].shape, f['fields/velocity'].attrs['unit']); "
      "print('%.17g' % f['particles/x'][5], f['materials'].asstr()[0], len(f['scene'].asstr()[()]))",
      dir / "p.h5");
  std::istringstream in(out);
  std::string format, time, kind, geometry, shape0, shape1, unit, x5, mat0, mat0b;
  int version = 0;
  long step = 0, nDensity = 0, sceneChars = 0;
  in >> format >> version >> time >> step >> kind >> geometry >> nDensity >> shape0 >> shape1 >> unit >>
      x5 >> mat0 >> mat0b >> sceneChars;
  EXPECT_EQ(format, "hvi-snapshot") << out;
  EXPECT_EQ(version, 1);
  EXPECT_TRUE(sameBits(std::strtod(time.c_str(), nullptr), snap.time)) << time;
  EXPECT_EQ(step, snap.step);
  EXPECT_EQ(kind, "particles");
  EXPECT_EQ(geometry, "rz");
  EXPECT_EQ(nDensity, 321);
  EXPECT_EQ(shape0 + shape1, "(321,2)");
  EXPECT_EQ(unit, "cm/us");
  EXPECT_TRUE(sameBits(std::strtod(x5.c_str(), nullptr), snap.positions[5].x)) << x5;
  EXPECT_EQ(mat0 + " " + mat0b, snap.materialNames[0]);
  // Python counts characters, not bytes: the scene has two 2-byte and one 3-byte character.
  EXPECT_EQ(sceneChars, static_cast<long>(sampleScene().size()) - 4);
}

}  // namespace
}  // namespace hvi::io::test
