#include "common/fit/fit_start_normals.h"

namespace primitive_edit {

Eigen::MatrixX3d fit_start_normals(const FitSample& sample)
{
  if (sample.normals.rows())
    return sample.normals;
  return estimate_normals_from_quadric(sample.points, sample.weights);
}

} // namespace primitive_edit
