//! @file VTK XML writers for ParaView: particles (.vtu), grid (.vti), marker lines (.vtp).
#include <stdexcept>

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "hvi/common/atomic_file.hpp"
#include "hvi/io/output.hpp"

namespace hvi::io {
namespace fs = std::filesystem;

namespace {

// The simulation plane (x or r, z) is laid onto VTK's (x, y) so that ParaView's default view
// (looking down -z at the x-y plane) shows it without rotating the camera.

//! ParaView titles its colour legend with the array name, and has no other place for a unit:
//! "density [g/cm^3]". Dimensionless fields (unit "1": material, object) keep the bare name, so
//! the marker lines' "material" array and the grid's are the same array to ParaView.
std::string vtkArrayName(const Field& f) {
  if (f.unit.empty() || f.unit == "1") return f.name;
  return f.name + " [" + f.unit + "]";
}

vtkNew<vtkDoubleArray> toVtkArray(const Field& f, long count) {
  // ParaView treats a 3-component array as a vector (glyphs, stream lines); a 2-component one
  // would not be, so 2-vectors are padded with a zero third component.
  const int c = f.components == 2 ? 3 : f.components;
  vtkNew<vtkDoubleArray> a;
  a->SetName(vtkArrayName(f).c_str());
  a->SetNumberOfComponents(c);
  a->SetNumberOfTuples(count);
  double* out = a->GetPointer(0);
  for (long i = 0; i < count; ++i)
    for (int j = 0; j < c; ++j)
      out[i * c + j] = j < f.components ? f.data[static_cast<std::size_t>(i * f.components + j)] : 0.0;
  return a;
}

vtkNew<vtkStringArray> stringArray(const char* name, const std::vector<std::string>& values) {
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), values[i]);
  return a;
}

//! TIME and CYCLE are the names ParaView's readers look for; the rest documents the dataset.
void addFieldData(vtkDataObject* data, const Snapshot& snap) {
  vtkNew<vtkDoubleArray> time;
  time->SetName("TIME");
  time->InsertNextValue(snap.time);
  vtkNew<vtkTypeInt64Array> cycle;
  cycle->SetName("CYCLE");
  cycle->InsertNextValue(snap.step);
  vtkFieldData* fd = data->GetFieldData();
  fd->AddArray(time);
  fd->AddArray(cycle);
  std::vector<std::string> fieldUnits;
  for (const Field& f : snap.fields) fieldUnits.push_back(f.name + " [" + f.unit + "]");
  fd->AddArray(stringArray("field_units", fieldUnits));
  fd->AddArray(stringArray("solver", {snap.solver}));
  fd->AddArray(stringArray("geometry", {std::string(toString(snap.geometry))}));
  fd->AddArray(stringArray("material_names", snap.materialNames));
  fd->AddArray(stringArray("object_names", snap.objectNames));
}

//! Binary appended zlib-compressed XML, written to the temporary name and renamed.
template <class Writer>
void writeXml(const fs::path& target, vtkDataObject* data) {
  writeAtomically(target, [&](const fs::path& tmp) {
    vtkNew<Writer> w;
    w->SetFileName(tmp.c_str());
    w->SetInputData(data);
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOff();
    w->SetCompressorTypeToZLib();
    // Level 1: doubles barely compress further at higher levels, and output must not stall
    // the run; integer-valued fields (material, object) still shrink tenfold.
    w->SetCompressionLevel(1);
    w->SetHeaderTypeToUInt64();  // arrays beyond 4 GiB stay readable
    if (w->Write() != 1 || w->GetErrorCode() != vtkErrorCode::NoError)
      throw std::runtime_error(fmt::format("cannot write VTK file {}: {}", target.string(),
                                           vtkErrorCode::GetStringFromErrorCode(w->GetErrorCode())));
  });
}

vtkNew<vtkPoints> pointsOf(const std::vector<Vec2>& positions) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    pts->SetPoint(static_cast<vtkIdType>(i), positions[i].x, positions[i].z, 0.0);
  return pts;
}

void writeParticles(const fs::path& file, const Snapshot& snap) {
  vtkNew<vtkUnstructuredGrid> ug;
  ug->SetPoints(pointsOf(snap.positions));
  const auto n = static_cast<vtkIdType>(snap.positions.size());
  // One VTK_VERTEX per particle so that cell-based filters (threshold, selection) work on them.
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i) {
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(n, n);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  ug->SetCells(VTK_VERTEX, cells);
  for (const Field& f : snap.fields) ug->GetPointData()->AddArray(toVtkArray(f, snap.count()));
  addFieldData(ug, snap);
  writeXml<vtkXMLUnstructuredGridWriter>(file, ug);
}

void writeGrid(const fs::path& file, const Snapshot& snap) {
  const GridSpec& g = snap.grid;
  vtkNew<vtkImageData> img;
  // Extent counts points; the cells (values) are the nx x nz between them, i fastest as in
  // GridSpec, which is VTK's own cell order.
  img->SetExtent(0, g.nx, 0, g.nz, 0, 0);
  img->SetOrigin(g.x0, g.z0, 0.0);
  img->SetSpacing(g.dx, g.dz, 1.0);
  for (const Field& f : snap.fields) img->GetCellData()->AddArray(toVtkArray(f, snap.count()));
  addFieldData(img, snap);
  writeXml<vtkXMLImageDataWriter>(file, img);
}

//! The material of each object, read off the snapshot's cells (the TVD grid carries both
//! "object" and "material"); -1 where an object owns no cell (it left the grid).
std::vector<int> objectMaterials(const Snapshot& snap) {
  std::vector<int> mat(snap.objectNames.size(), -1);
  const Field* obj = snap.find("object");
  const Field* m = snap.find("material");
  if (obj == nullptr || m == nullptr || obj->components != 1 || m->components != 1) return mat;
  for (std::size_t i = 0; i < obj->data.size() && i < m->data.size(); ++i) {
    const double o = obj->data[i];
    if (o >= 0.0 && o < static_cast<double>(mat.size()) && m->data[i] >= 0.0)
      mat[static_cast<std::size_t>(o)] = static_cast<int>(m->data[i]);
  }
  return mat;
}

void writeMarkers(const fs::path& file, const Snapshot& snap) {
  std::vector<Vec2> all;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> object;
  object->SetName("object");
  // Colouring the multiblock series by a grid array paints blocks without that array in the NaN
  // colour; a "material" array on the lines lets "colour by material" draw them sensibly.
  const std::vector<int> objectMaterial = objectMaterials(snap);
  vtkNew<vtkIntArray> material;
  material->SetName("material");
  vtkNew<vtkIntArray> closed;
  closed->SetName("closed");
  for (const Polyline& line : snap.markers) {
    if (line.points.empty()) continue;
    const auto first = static_cast<vtkIdType>(all.size());
    all.insert(all.end(), line.points.begin(), line.points.end());
    const auto n = static_cast<vtkIdType>(line.points.size());
    // A closed line repeats its first point: VTK has no closed polyline cell.
    const bool close = line.closed && n > 2;
    lines->InsertNextCell(n + (close ? 1 : 0));
    for (vtkIdType i = 0; i < n; ++i) lines->InsertCellPoint(first + i);
    if (close) lines->InsertCellPoint(first);
    object->InsertNextValue(line.object);
    material->InsertNextValue(line.object >= 0 &&
                                      static_cast<std::size_t>(line.object) < objectMaterial.size()
                                  ? objectMaterial[static_cast<std::size_t>(line.object)]
                                  : -1);
    closed->InsertNextValue(line.closed ? 1 : 0);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pointsOf(all));
  pd->SetLines(lines);
  pd->GetCellData()->AddArray(object);
  pd->GetCellData()->AddArray(material);
  pd->GetCellData()->AddArray(closed);
  addFieldData(pd, snap);
  writeXml<vtkXMLPolyDataWriter>(file, pd);
}

fs::path withSuffix(const fs::path& stem, const char* suffix) {
  return stem.parent_path() / (stem.filename().string() + suffix);
}

}  // namespace

std::vector<fs::path> writeVtk(const fs::path& stem, const Snapshot& snap) {
  validateSnapshot(snap);
  std::vector<fs::path> written;
  if (snap.kind == Snapshot::Kind::Particles) {
    written.push_back(withSuffix(stem, ".vtu"));
    writeParticles(written.back(), snap);
  } else {
    written.push_back(withSuffix(stem, ".vti"));
    writeGrid(written.back(), snap);
  }
  if (!snap.markers.empty()) {
    written.push_back(withSuffix(stem, "_markers.vtp"));
    writeMarkers(written.back(), snap);
  }
  return written;
}

}  // namespace hvi::io
