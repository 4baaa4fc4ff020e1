// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every VTK file Lightcone writes (export, curvature grids, shadow outlines) as bytes for the
// atomic writer: VTK's XML format in binary mode, as ParaView writes it, with the writing program
// named in the data's field data ("lightcone_version", io/provenance).
#include <string>

class vtkDataObject;
class vtkXMLWriter;

namespace lc::cli {

// Throws std::runtime_error naming `name` when VTK's writer fails. `data` itself is not changed.
std::string vtkXmlBytes(vtkXMLWriter* writer, vtkDataObject* data, const std::string& name);

}  // namespace lc::cli
