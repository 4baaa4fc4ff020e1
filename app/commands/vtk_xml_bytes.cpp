// SPDX-License-Identifier: BSD-3-Clause
#include "app/commands/vtk_xml_bytes.hpp"

#include "readers/io/provenance.hpp"

#include <vtkDataObject.h>
#include <vtkNew.h>
#include <vtkFieldData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLWriter.h>

#include <stdexcept>

namespace lc::cli {

std::string vtkXmlBytes(vtkXMLWriter* writer, vtkDataObject* data, const std::string& name) {
    // A shallow copy carries the stamp: the caller's data (a filter's output) stays as it was.
    vtkSmartPointer<vtkDataObject> stamped = vtkSmartPointer<vtkDataObject>::Take(data->NewInstance());
    stamped->ShallowCopy(data);
    vtkSmartPointer<vtkFieldData> fields = vtkSmartPointer<vtkFieldData>::New();
    if (data->GetFieldData()) fields->ShallowCopy(data->GetFieldData());
    vtkNew<vtkStringArray> version;
    version->SetName("lightcone_version");
    version->InsertNextValue(io::softwareName());
    fields->AddArray(version);
    stamped->SetFieldData(fields);
    writer->SetInputData(stamped);
    writer->SetDataModeToBinary();
    writer->WriteToOutputStringOn();
    if (writer->Write() != 1) throw std::runtime_error("cannot encode '" + name + "' (VTK writer error)");
    return writer->GetOutputString();
}

}  // namespace lc::cli
