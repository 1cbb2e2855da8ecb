#pragma once
// Writes an OpenCASCADE shape given in metres as a STEP file in metres: the CAD solids that the
// tests build on the fly (OpenCASCADE's default unit is the millimetre).
#include <gtest/gtest.h>

#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Shape.hxx>
#include <UnitsMethods.hxx>
#include <filesystem>

namespace curvsph::test {

inline void write_step(const TopoDS_Shape& shape, const std::filesystem::path& path) {
  STEPControl_Controller::Init();
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  Interface_Static::SetCVal("write.step.unit", "M");
  UnitsMethods::SetCasCadeLengthUnit(1000.0);
  STEPControl_Writer w;
  ASSERT_EQ(w.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
  ASSERT_EQ(w.Write(path.c_str()), IFSelect_RetDone);
}

}  // namespace curvsph::test
