#include "StatisticsPictures.h"

#include "Pictures.h"

#include "vtkChart.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"

namespace surfacemap
{

void writeExplainedVariancePicture(const std::vector<double>& fractions, const std::string& path)
{
  ChartSeries percent;
  for (std::size_t m = 0; m < fractions.size(); ++m)
  {
    percent.x.push_back(m + 1.0);
    percent.y.push_back(100.0 * fractions[m]);
  }
  ChartPicture chart;
  chart.type = vtkChart::BAR;
  chart.series = { percent };
  chart.xTitle = "mode";
  chart.yTitle = "explained variance (%)";
  chart.title = "Explained variance per mode";
  chart.integerX = true;
  writeChart(chart, path);
}

void writeScoresPicture(const std::vector<double>& scores, int modes, const std::string& path)
{
  ChartSeries specimens;
  const std::size_t n = modes > 0 ? scores.size() / modes : 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    specimens.x.push_back(modes >= 2 ? scores[i * modes] : static_cast<double>(i));
    specimens.y.push_back(scores[i * modes + (modes >= 2 ? 1 : 0)]);
  }
  ChartPicture chart;
  chart.type = vtkChart::POINTS;
  chart.series = { specimens };
  chart.xTitle = modes >= 2 ? "score on mode 1" : "specimen";
  chart.yTitle = modes >= 2 ? "score on mode 2" : "score on mode 1";
  chart.title = modes >= 2 ? "Specimens on the first two modes" : "Specimens on mode 1";
  writeChart(chart, path);
}

void writeSpreadPicture(vtkPolyData* mean, const std::string& path)
{
  double range[2] = { 0.0, 1.0 };
  mean->GetPointData()->GetArray("StandardDeviation")->GetRange(range, 0);
  vtkSmartPointer<vtkLookupTable> colours = rainbowTable(range); // blue: little spread, red: much
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(mean);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("StandardDeviation");
  mapper->SetLookupTable(colours);
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();
  mapper->InterpolateScalarsBeforeMappingOn();
  writeSurfacePicture({ { mapper, "" } }, colours, "standard deviation", path);
}

} // namespace surfacemap
