# SPDX-License-Identifier: BSD-3-Clause
# lightcone_precompile_headers(TARGET KIND): the heavy third-party headers a target's files share,
# compiled once per target (target_precompile_headers). KIND is the heaviest library the target
# uses: tests (Eigen, the standard library, GoogleTest), vtk_tests and views_tests (+ VTK's data
# and rendering classes), qt (+ Qt Widgets and VTK's Qt widget), qt_tests.
# Used where parsing headers dominates (the test programs, the workbench): measured on 2 cores,
# core_tests + view_tests + gui_tests built in 266 s with them, 286 s without. The libraries of
# the command line (core at -O3, filters, views) spend their time generating code: there the
# headers made `lightcone` slower (about 240 s against 229 s), so they do without.
# LIGHTCONE_PRECOMPILED_HEADERS=OFF builds without them (every file still includes what it uses:
# a build with it OFF checks that).
option(LIGHTCONE_PRECOMPILED_HEADERS "Precompile the heavy third-party headers (Eigen, VTK, Qt, GoogleTest)" ON)

set(LIGHTCONE_PCH_core <Eigen/Dense> <Eigen/Geometry> <algorithm> <cmath> <functional> <memory> <stdexcept>
    <string> <vector>)
set(LIGHTCONE_PCH_vtk ${LIGHTCONE_PCH_core} <vtkCellArray.h> <vtkDoubleArray.h> <vtkInformation.h>
    <vtkInformationVector.h> <vtkNew.h> <vtkObjectFactory.h> <vtkPointData.h> <vtkPoints.h> <vtkPolyData.h>
    <vtkSmartPointer.h>)
set(LIGHTCONE_PCH_views ${LIGHTCONE_PCH_vtk} <vtkActor.h> <vtkOpenGLRenderWindow.h> <vtkRenderWindow.h>
    <vtkRenderer.h> <vtkShaderProgram.h>)
set(LIGHTCONE_PCH_qt ${LIGHTCONE_PCH_views} <QAction> <QDockWidget> <QLabel> <QMainWindow> <QString>
    <QVBoxLayout> <QWidget> <QVTKOpenGLNativeWidget.h>)
set(LIGHTCONE_PCH_tests ${LIGHTCONE_PCH_core} <gtest/gtest.h>)
set(LIGHTCONE_PCH_vtk_tests ${LIGHTCONE_PCH_vtk} <gtest/gtest.h>)
set(LIGHTCONE_PCH_views_tests ${LIGHTCONE_PCH_views} <gtest/gtest.h>)
set(LIGHTCONE_PCH_qt_tests ${LIGHTCONE_PCH_qt} <gtest/gtest.h> <QTest>)

function(lightcone_precompile_headers target kind)
  if(NOT LIGHTCONE_PRECOMPILED_HEADERS)
    return()
  endif()
  if(NOT DEFINED LIGHTCONE_PCH_${kind})
    message(FATAL_ERROR "lightcone_precompile_headers(${target} ${kind}): no such kind")
  endif()
  target_precompile_headers(${target} PRIVATE ${LIGHTCONE_PCH_${kind}})
endfunction()
