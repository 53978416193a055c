#include "filter_measure_accuracy.h"

#include "common/measure/measure_accuracy.h"
#include "common/mesh/check_mesh_input.h"
#include "common/mesh/sample_surface_uniform.h"

#include <vcg/complex/algorithms/update/color.h>

#include <cmath>

using namespace primitive_edit;
using namespace primitive_edit::meshlab;

namespace {

constexpr int kMaxSamples = 100000000;  // 2.4 GB of sample coordinates; beyond that is a typo

// MeshLab keeps a per-layer placement matrix apart from the vertex coordinates.
Eigen::Affine3d layer_to_world(const CMeshO& m)
{
  Eigen::Affine3d a;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      a.matrix()(i, j) = double(m.Tr.ElementAt(i, j));
  return a;
}

} // namespace

QString MeasureAccuracyFilters::pluginName() const { return "FilterMeasureAccuracy"; }

std::vector<FilterDefinition> MeasureAccuracyFilters::filters() const
{
  FilterDefinition d;
  d.id = MEASURE_ACCURACY;
  d.name = "Measure: Accuracy Against Reference";
  d.python_name = "measure_accuracy_against_reference";
  d.info = "Measures how close a mesh is to a reference (CAD) mesh, as in section 3 of Yang, Oh, Choi, "
           "<i>Mesh Editing with an Intuitive User Interface</i>: samples are spread uniformly by area over "
           "the measured mesh, the shortest distance of each to the reference surface is found, and the "
           "accuracy is the share of samples within the tolerance (the error permission). The log gives that "
           "share, the mean, RMS and max distance and a histogram. Optionally writes the distance of each "
           "vertex to the reference into the vertex quality of the measured mesh and colours it as a "
           "deviation map (blue on the reference, green at the tolerance, red from twice the tolerance). "
           "Both layers' transformation matrices are taken into account. The meshes must be roughly "
           "aligned: far samples are slow to measure.";
  d.menus = MenuMeasure;
  d.postconditions = MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
  d.two_meshes = true;
  return {d};
}

void MeasureAccuracyFilters::parameters(int, MeshDocument& md, ParameterList& parlst) const
{
  MeshModel* reference = md.mm();
  for (MeshModel* m : document_meshes(md))
    if (m != md.mm()) {
      reference = m;
      break;
    }
  const int measured_id = md.mm() != nullptr ? md.mm()->id() : 0;
  const int reference_id = reference != nullptr ? reference->id() : 0;
  parlst.addMesh("MeasuredMesh", measured_id, "Measured Mesh",
                           "The mesh whose accuracy is measured (e.g. the scan, or the edited scan). "
                           "The samples are taken on its surface.");
  parlst.addMesh("ReferenceMesh", reference_id, "Reference Mesh",
                           "The reference surface (e.g. the CAD model) the samples' distances are measured to. "
                           "Must be a different layer with faces.");
  parlst.addInt("Samples", 1000000, "Samples",
                          "Number of points sampled uniformly by area on the measured mesh (1 to 100000000). "
                          "The paper uses one million.");
  parlst.addFloat("Tolerance", 0.42, "Tolerance",
                            "The error permission, in mesh units (mm for the paper's part): a sample is "
                            "accurate when its distance to the reference is at most this. Must be positive.");
  parlst.addInt("Seed", 0, "Random Seed",
                          "Seed of the sampling (0 or more): the same seed gives the same samples and figures.");
  parlst.addBool("DeviationMap", false, "Colour Deviation Map",
                           "Also store each vertex's distance to the reference in the vertex quality of the "
                           "measured mesh and colour it: blue on the reference, green at the tolerance, red at "
                           "twice the tolerance and beyond.");
}

Status MeasureAccuracyFilters::apply(int, FilterRun& run)
{
  const QString name = "Measure: Accuracy Against Reference";
  const FilterArguments& parlst = run.arguments;
  const Progress& progress = run.progress;
  MeshModel* measured = parlst.getMesh("MeasuredMesh");
  MeshModel* reference = parlst.getMesh("ReferenceMesh");
  const int sample_count = parlst.getInt("Samples");
  const double tolerance = parlst.getFloat("Tolerance");
  const int seed = parlst.getInt("Seed");
  const bool deviation_map = parlst.getBool("DeviationMap");

  if (measured == nullptr || reference == nullptr)
    return fail(name + ": choose both the measured and the reference mesh.");
  if (measured == reference)
    return fail(name + ": the measured and the reference mesh are the same layer; choose two different layers.");
  if (sample_count < 1 || sample_count > kMaxSamples)
    return fail(name + QString(": Samples must be between 1 and %1 (it is %2).").arg(kMaxSamples).arg(sample_count));
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    return fail(name + QString(": Tolerance must be a positive number of mesh units (it is %1).").arg(tolerance));
  if (seed < 0)
    return fail(name + QString(": Seed must be 0 or more (it is %1).").arg(seed));
  const QString measured_name = name + ": measured mesh '" + measured->label() + "'";
  const QString reference_name = name + ": reference mesh '" + reference->label() + "'";
  if (const Status usable = check_mesh_input(measured->cm); !usable)
    return fail(measured_name, usable);
  if (const Status usable = check_mesh_input(reference->cm); !usable)
    return fail(reference_name, usable);

  const Eigen::Affine3d measured_to_world = layer_to_world(measured->cm);
  const Eigen::Affine3d reference_to_world = layer_to_world(reference->cm);

  report_progress(progress, 0, "Sampling the measured mesh");
  Eigen::MatrixX3d samples;
  if (const Status sampled = sample_surface_uniform(measured->cm, Eigen::Index(sample_count), std::uint64_t(seed), &samples);
      !sampled)
    return fail(measured_name, sampled);
  samples = (samples * measured_to_world.linear().transpose()).rowwise() + measured_to_world.translation().transpose();

  report_progress(progress, 5, "Indexing the reference mesh");
  SurfaceDistanceIndex index(reference->cm, reference_to_world);
  if (!index.status())
    return fail(reference_name, index.status());

  const AccuracyReport r =
      measure_accuracy(samples, index, tolerance, false, progress_range(progress, 10, deviation_map ? 80 : 100));
  if (!r.status)
    return fail(name, r.status);

  Eigen::VectorXd vertex_distance;
  if (deviation_map) {
    const Status mapped =
        vertex_distances(measured->cm, index, vertex_distance, measured_to_world, progress_range(progress, 80, 100));
    if (!mapped)
      return fail(name + ": deviation map of '" + measured->label() + "'", mapped);
  }

  run.logf("Accuracy: %.1f%% of %d samples within %g (mean %.3f, RMS %.3f, max %.3f)", 100.0 * r.within_tolerance_share,
      int(r.sample_count), tolerance, r.mean, r.rms, r.max);
  run.logf("Accuracy: measured '%s' against reference '%s' (%d faces indexed, %d degenerate skipped), seed %d",
      qUtf8Printable(measured->label()), qUtf8Printable(reference->label()), int(index.triangle_count()),
      int(index.skipped_face_count()), seed);
  for (int b = 0; b <= kAccuracyHistogramBins; ++b) {
    const double share = double(r.histogram[size_t(b)]) / double(r.sample_count);
    const QString bar(int(std::lround(40.0 * share)), QChar('#'));
    if (b < kAccuracyHistogramBins)
      run.logf("Accuracy histogram [%.3f, %.3f): %5.1f%% %s", b * r.histogram_bin_width, (b + 1) * r.histogram_bin_width,
          100.0 * share, qUtf8Printable(bar));
    else
      run.logf("Accuracy histogram >= %.3f: %5.1f%% %s", b * r.histogram_bin_width, 100.0 * share, qUtf8Printable(bar));
  }

  if (deviation_map) {
    measured->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
    for (auto& v : measured->cm.vert)
      if (!v.IsD())
        v.Q() = Scalarm(vertex_distance(Eigen::Index(vcg::tri::Index(measured->cm, v))));
    // Reversed range: blue at 0, green at the tolerance, red at twice the tolerance and beyond.
    vcg::tri::UpdateColor<CMeshO>::PerVertexQualityRamp(measured->cm, Scalarm(2.0 * tolerance), Scalarm(0.0));
    run.logf("Accuracy: deviation map written to the vertex quality and colour of '%s' (max vertex distance %.3f)",
        qUtf8Printable(measured->label()), vertex_distance.maxCoeff());
  }
  return Status::success();
}

