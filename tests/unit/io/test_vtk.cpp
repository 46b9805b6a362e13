//! @file VTK output read back with VTK's own XML readers (what ParaView uses to open it).
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "hvi/io/output.hpp"
#include "test_support.hpp"

namespace hvi::io::test {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

double fieldValue(vtkDataObject* d, const char* name) {
  vtkDataArray* a = d->GetFieldData()->GetArray(name);
  if (!a) {
    ADD_FAILURE() << "no field data " << name;
    return 0.0;
  }
  return a->GetTuple1(0);
}

void expectBinaryCompressed(const std::filesystem::path& p) {
  // Raw appended binary + zlib: the compact form; an ASCII or base64 file would still open but
  // be several times larger and slower.
  const std::string head = slurp(p).substr(0, 4096);
  EXPECT_NE(head.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(head.find("format=\"appended\""), std::string::npos);
  EXPECT_NE(slurp(p).find("<AppendedData encoding=\"raw\">"), std::string::npos);
}

TEST(Vtk, ParticlesOpenAsVerticesInTheXyPlaneWithTheirFields) {
  ScratchDir dir;
  const Snapshot snap = particleSnapshot(500);
  const auto files = writeVtk(dir / "p_0001", snap);
  ASSERT_EQ(files, std::vector<std::filesystem::path>{dir / "p_0001.vtu"});
  expectBinaryCompressed(files[0]);

  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(files[0].c_str());
  r->Update();
  vtkUnstructuredGrid* ug = r->GetOutput();
  ASSERT_EQ(ug->GetNumberOfPoints(), 500);
  ASSERT_EQ(ug->GetNumberOfCells(), 500);
  EXPECT_EQ(ug->GetCellType(123), VTK_VERTEX);
  for (vtkIdType i : {0, 77, 499}) {
    double x[3];
    ug->GetPoint(i, x);
    EXPECT_TRUE(sameBits(x[0], snap.positions[static_cast<std::size_t>(i)].x));
    EXPECT_TRUE(sameBits(x[1], snap.positions[static_cast<std::size_t>(i)].z));
    EXPECT_EQ(x[2], 0.0);
  }
  // Lossless compression: values come back bit for bit, special values included.
  vtkDataArray* rho = ug->GetPointData()->GetArray("density [g/cm^3]");
  ASSERT_NE(rho, nullptr);
  for (vtkIdType i = 0; i < 500; ++i)
    ASSERT_TRUE(sameBits(rho->GetTuple1(i), snap.fields[0].data[static_cast<std::size_t>(i)])) << i;
  vtkDataArray* vel = ug->GetPointData()->GetArray("velocity [cm/us]");
  ASSERT_NE(vel, nullptr);
  ASSERT_EQ(vel->GetNumberOfComponents(), 3);  // padded for ParaView's vector tools
  EXPECT_EQ(vel->GetComponent(42, 0), snap.fields[1].data[84]);
  EXPECT_EQ(vel->GetComponent(42, 1), snap.fields[1].data[85]);
  EXPECT_EQ(vel->GetComponent(42, 2), 0.0);
  EXPECT_EQ(ug->GetPointData()->GetArray("deviatoric_stress [Mbar]")->GetNumberOfComponents(), 4);
  EXPECT_EQ(fieldValue(ug, "TIME"), snap.time);
  EXPECT_EQ(fieldValue(ug, "CYCLE"), static_cast<double>(snap.step));
  auto* units = vtkStringArray::SafeDownCast(ug->GetFieldData()->GetAbstractArray("field_units"));
  ASSERT_NE(units, nullptr);
  EXPECT_EQ(units->GetValue(1), "velocity [cm/us]");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p_0001.vtu"});
}

TEST(Vtk, GridOpensAsImageWithCellDataInGridSpecOrder) {
  ScratchDir dir;
  const Snapshot snap = gridSnapshot(30, 20);
  const auto files = writeVtk(dir / "g", snap);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0], dir / "g.vti");
  EXPECT_EQ(files[1], dir / "g_markers.vtp");
  expectBinaryCompressed(files[0]);

  vtkNew<vtkXMLImageDataReader> r;
  r->SetFileName(files[0].c_str());
  r->Update();
  vtkImageData* img = r->GetOutput();
  int dims[3];
  img->GetDimensions(dims);
  EXPECT_EQ(dims[0], 31);
  EXPECT_EQ(dims[1], 21);
  EXPECT_EQ(dims[2], 1);
  ASSERT_EQ(img->GetNumberOfCells(), 600);
  vtkDataArray* rho = img->GetCellData()->GetArray("density [g/cm^3]");
  ASSERT_NE(rho, nullptr);
  // density = 1000 k + i, so each cell proves both the ordering and the cell's position:
  // its VTK bounds must be the GridSpec cell (x0 + i dx .. x0 + (i+1) dx, z0 + k dz ..).
  for (int k : {0, 7, 19})
    for (int i : {0, 13, 29}) {
      int ijk[3] = {i, k, 0};
      const vtkIdType cell = img->ComputeCellId(ijk);
      EXPECT_EQ(rho->GetTuple1(cell), 1000.0 * k + i);
      double b[6];
      img->GetCellBounds(cell, b);
      const GridSpec& g = snap.grid;
      EXPECT_NEAR(0.5 * (b[0] + b[1]), g.x0 + (i + 0.5) * g.dx, 1e-12);  // origin + index * spacing
      EXPECT_NEAR(0.5 * (b[2] + b[3]), g.z0 + (k + 0.5) * g.dz, 1e-12);
    }
  EXPECT_EQ(img->GetCellData()->GetArray("volume_fraction")->GetNumberOfComponents(), 3);
  EXPECT_EQ(img->GetCellData()->GetArray("velocity [cm/us]")->GetComponent(31, 2), 0.0);
  EXPECT_EQ(fieldValue(img, "TIME"), snap.time);
}

TEST(Vtk, MarkerLinesOpenAsPolylinesWithObjectIds) {
  ScratchDir dir;
  const Snapshot snap = gridSnapshot(4, 4);
  const auto files = writeVtk(dir / "m", snap);
  ASSERT_EQ(files.size(), 2u);
  expectBinaryCompressed(files[1]);
  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName(files[1].c_str());
  r->Update();
  vtkPolyData* pd = r->GetOutput();
  // The empty marker has no cell; the closed circle repeats its first point.
  ASSERT_EQ(pd->GetNumberOfLines(), 2);
  EXPECT_EQ(pd->GetNumberOfPoints(), 43);
  vtkNew<vtkIdList> ids;
  pd->GetCellPoints(0, ids);
  ASSERT_EQ(ids->GetNumberOfIds(), 41);
  EXPECT_EQ(ids->GetId(40), ids->GetId(0));
  double x[3];
  pd->GetPoint(ids->GetId(10), x);
  EXPECT_EQ(x[0], snap.markers[0].points[10].x);
  EXPECT_EQ(x[1], snap.markers[0].points[10].z);
  pd->GetCellPoints(1, ids);
  EXPECT_EQ(ids->GetNumberOfIds(), 3);
  vtkDataArray* object = pd->GetCellData()->GetArray("object");
  ASSERT_NE(object, nullptr);
  EXPECT_EQ(object->GetTuple1(0), 0.0);
  EXPECT_EQ(object->GetTuple1(1), 1.0);
  EXPECT_EQ(fieldValue(pd, "TIME"), snap.time);
}

// ParaView titles the colour legend with the array name: the unit must be in it (issue 11).
// Dimensionless arrays keep their bare names.
TEST(Vtk, ArrayNamesCarryTheirUnits) {
  ScratchDir dir;
  const auto files = writeVtk(dir / "p", particleSnapshot(5));
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(files[0].c_str());
  r->Update();
  vtkPointData* pd = r->GetOutput()->GetPointData();
  std::vector<std::string> names;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) names.emplace_back(pd->GetArrayName(i));
  EXPECT_EQ(names, (std::vector<std::string>{"density [g/cm^3]", "velocity [cm/us]",
                                             "deviatoric_stress [Mbar]", "material"}));
}

// A grid series with markers is a multiblock in ParaView; colouring it by "material" must find
// that array on the line block too (not the NaN colour), with each line's object's material.
TEST(Vtk, MarkerLinesCarryTheMaterialOfTheirObject) {
  ScratchDir dir;
  Snapshot snap = gridSnapshot(4, 4);
  const long n = snap.count();
  Field obj{"object", "1", 1, std::vector<double>(static_cast<std::size_t>(n), -1.0)};
  Field mat{"material", "1", 1, std::vector<double>(static_cast<std::size_t>(n), -1.0)};
  obj.data[0] = 0.0;  // the circle (object 0) is of material 1
  mat.data[0] = 1.0;
  obj.data[5] = 1.0;  // the plate (object 1) of material 0
  mat.data[5] = 0.0;
  snap.fields.push_back(obj);
  snap.fields.push_back(mat);
  const auto files = writeVtk(dir / "m", snap);
  ASSERT_EQ(files.size(), 2u);
  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName(files[1].c_str());
  r->Update();
  vtkDataArray* material = r->GetOutput()->GetCellData()->GetArray("material");
  ASSERT_NE(material, nullptr);
  ASSERT_EQ(material->GetNumberOfTuples(), 2);
  EXPECT_EQ(material->GetTuple1(0), 1.0);
  EXPECT_EQ(material->GetTuple1(1), 0.0);
  // The grid's material array has the same name, so one colour map covers both blocks.
  vtkNew<vtkXMLImageDataReader> g;
  g->SetFileName(files[0].c_str());
  g->Update();
  EXPECT_NE(g->GetOutput()->GetCellData()->GetArray("material"), nullptr);
  // Without object and material cells the lines still get the array, as -1 (unknown).
  const auto bare = writeVtk(dir / "b", gridSnapshot(4, 4));
  vtkNew<vtkXMLPolyDataReader> b;
  b->SetFileName(bare[1].c_str());
  b->Update();
  vtkDataArray* none = b->GetOutput()->GetCellData()->GetArray("material");
  ASSERT_NE(none, nullptr);
  EXPECT_EQ(none->GetTuple1(0), -1.0);
}

TEST(Vtk, ParticlesWithoutMarkersWriteNoPolyData) {
  ScratchDir dir;
  EXPECT_EQ(writeVtk(dir / "sub/p", particleSnapshot(3)).size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(dir / "sub/p.vtu"));
}

}  // namespace
}  // namespace hvi::io::test
