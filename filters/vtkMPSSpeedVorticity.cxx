#include "vtkMPSSpeedVorticity.h"

#include <cmath>
#include <limits>
#include <vector>

#include "MPSFrame.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMPSKernel.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"

vtkStandardNewMacro(vtkMPSSpeedVorticity);

vtkMPSSpeedVorticity::vtkMPSSpeedVorticity()
    : Gradient(MPS), Radius(0.0), N0(0.0), VelocityArrayName(nullptr) {
  this->SetVelocityArrayName("velocity");
}

vtkMPSSpeedVorticity::~vtkMPSSpeedVorticity() {
  this->SetVelocityArrayName(nullptr);
}

namespace {

struct VorticityWorker {
  vtkPolyData* Frame;
  vtkStaticPointLocator* Locator;
  vtkDataArray* Velocity;
  const std::vector<char>* Fluid;
  double Re;
  double N0;
  bool Corrected;
  vtkDoubleArray* Speed;
  vtkDoubleArray* Vorticity;
  vtkSMPThreadLocalObject<vtkIdList> Ids;

  void Initialize() {}

  void operator()(vtkIdType begin, vtkIdType end) {
    vtkIdList* ids = this->Ids.Local();
    double xi[3], xj[3], vi[3], vj[3];
    for (vtkIdType i = begin; i < end; ++i) {
      this->Velocity->GetTuple(i, vi);
      this->Speed->SetValue(i, std::hypot(vi[0], vi[1]));
      if (!(*this->Fluid)[static_cast<size_t>(i)]) {
        this->Vorticity->SetValue(i, std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      this->Frame->GetPoint(i, xi);
      xi[2] = 0.0;
      this->Locator->FindPointsWithinRadius(this->Re, xi, ids);
      // g_u, g_v: sum_j (phi_j - phi_i) (r_j - r_i) W / r^2; m: sum_j W (r_j - r_i)(..)^T / r^2.
      double gux = 0, guy = 0, gvx = 0, gvy = 0, mxx = 0, mxy = 0, myy = 0;
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
        const vtkIdType j = ids->GetId(k);
        if (j == i) {
          continue;
        }
        this->Frame->GetPoint(j, xj);
        const double dx = xj[0] - xi[0], dy = xj[1] - xi[1];
        const double r2 = dx * dx + dy * dy;
        const double w = vtkMPSKernel::Weight(std::sqrt(r2), this->Re);
        if (w <= 0.0 || r2 <= 0.0) {
          continue;
        }
        this->Velocity->GetTuple(j, vj);
        const double f = w / r2;
        gux += (vj[0] - vi[0]) * dx * f;
        guy += (vj[0] - vi[0]) * dy * f;
        gvx += (vj[1] - vi[1]) * dx * f;
        gvy += (vj[1] - vi[1]) * dy * f;
        mxx += dx * dx * f;
        mxy += dx * dy * f;
        myy += dy * dy * f;
      }
      double dvdx = 2.0 / this->N0 * gvx, dudy = 2.0 / this->N0 * guy;
      if (this->Corrected) {
        // C = (m / n0)^-1, so the gradient is m^-1 g (n0 cancels). Near-singular m: keep MPS.
        const double det = mxx * myy - mxy * mxy;
        const double trace = mxx + myy;
        if (det > 1e-6 * trace * trace) {
          dvdx = (myy * gvx - mxy * gvy) / det;
          dudy = (-mxy * gux + mxx * guy) / det;
        }
      }
      this->Vorticity->SetValue(i, dvdx - dudy);
    }
  }

  void Reduce() {}
};

}  // namespace

int vtkMPSSpeedVorticity::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                      vtkInformationVector* outputVector) {
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output) {
    return 0;
  }
  output->ShallowCopy(input);
  const double re = wcmps_filters::FrameRadius(input, this->Radius);
  const double n0 =
      this->N0 > 0.0 ? this->N0 : wcmps_filters::FieldValue(input->GetFieldData(), "n0", 0.0);
  vtkDataArray* velocity =
      this->VelocityArrayName ? input->GetPointData()->GetArray(this->VelocityArrayName) : nullptr;
  if (re <= 0.0 || n0 <= 0.0) {
    vtkErrorMacro("The frame has no re or n0 field data and none was set.");
    return 0;
  }
  if (!velocity || velocity->GetNumberOfComponents() < 2) {
    vtkErrorMacro("The frame has no point array \""
                  << (this->VelocityArrayName ? this->VelocityArrayName : "")
                  << "\" of two or more components.");
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> speed;
  speed->SetName("speed");
  speed->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> vorticity;
  vorticity->SetName("vorticity");
  vorticity->SetNumberOfTuples(n);
  if (n > 0) {
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(input);
    locator->BuildLocator();
    const std::vector<char> fluid = wcmps_filters::FluidMask(input);
    VorticityWorker worker{input, locator,   velocity, &fluid, re, n0, this->Gradient == CORRECTED,
                           speed, vorticity, {}};
    vtkSMPTools::For(0, n, worker);
  }
  output->GetPointData()->AddArray(speed);
  output->GetPointData()->AddArray(vorticity);
  return 1;
}

void vtkMPSSpeedVorticity::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Gradient: " << (this->Gradient == CORRECTED ? "Corrected" : "MPS") << "\n";
  os << indent << "Radius: " << this->Radius << (this->Radius > 0.0 ? "" : " (re)") << "\n";
  os << indent << "N0: " << this->N0 << (this->N0 > 0.0 ? "" : " (n0)") << "\n";
  os << indent
     << "VelocityArrayName: " << (this->VelocityArrayName ? this->VelocityArrayName : "(none)")
     << "\n";
}
