// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVisibilityFigure.h"

#include "vrFilterSettingsText.h"
#include "vrNodeConversion.h"

#include <vtkImageData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace vr
{
namespace
{
/** Colours for branch ids that read on grey (Tableau 10). */
RGBPixelType
PaletteColor(int id, bool bright)
{
  static const std::array<std::array<unsigned char, 3>, 10> palette = { { { 31, 119, 180 },
                                                                          { 255, 127, 14 },
                                                                          { 44, 160, 44 },
                                                                          { 214, 39, 40 },
                                                                          { 148, 103, 189 },
                                                                          { 140, 86, 75 },
                                                                          { 227, 119, 194 },
                                                                          { 188, 189, 34 },
                                                                          { 23, 190, 207 },
                                                                          { 127, 127, 127 } } };
  const auto & rgb = palette[static_cast<std::size_t>(std::abs(id)) % palette.size()];
  RGBPixelType pixel;
  for (unsigned int c = 0; c < 3; ++c)
  {
    pixel[c] = bright ? static_cast<unsigned char>(std::min(255, rgb[c] + 90)) : rgb[c];
  }
  return pixel;
}

void
Plot(RGBImageType * image, long column, long row, const RGBPixelType & color)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  if (column >= 0 && row >= 0 && column < static_cast<long>(size[0]) && row < static_cast<long>(size[1]))
  {
    image->SetPixel({ { column, row } }, color);
  }
}

/** The count of pixels with a hidden label in each window of \a width x \a height: the window with the most. */
std::array<unsigned int, 2>
BusiestWindow(const LabelImageType * hidden, unsigned int width, unsigned int height)
{
  const auto                  size = hidden->GetLargestPossibleRegion().GetSize();
  const auto *                labels = hidden->GetBufferPointer();
  std::size_t                 best = 0;
  std::array<unsigned int, 2> corner{ 0, 0 };
  const unsigned int          step = std::max(4u, std::min(width, height) / 8);
  for (unsigned int y = 0; y + height <= size[1]; y += step)
  {
    for (unsigned int x = 0; x + width <= size[0]; x += step)
    {
      std::size_t count = 0;
      for (unsigned int j = y; j < y + height; ++j)
      {
        for (unsigned int i = x; i < x + width; ++i)
        {
          count += labels[static_cast<std::size_t>(j) * size[0] + i] != 0 ? 1 : 0;
        }
      }
      if (count > best)
      {
        best = count;
        corner = { x, y };
      }
    }
  }
  return corner;
}
} // namespace

void
DrawCenterlines(RGBImageType *                          image,
                const itk::CenterlineTree &             tree,
                const itk::CPRViewGeometry &            view,
                const std::vector<BranchOcclusionRow> & occlusions)
{
  for (const auto & branch : tree.GetBranches())
  {
    const auto row = std::find_if(
      occlusions.begin(), occlusions.end(), [&](const BranchOcclusionRow & r) { return r.BranchId == branch.Id; });
    const auto hiddenAt = [&](double p)
    {
      if (row == occlusions.end())
      {
        return false;
      }
      return std::any_of(row->HiddenStretches.begin(),
                         row->HiddenStretches.end(),
                         [p](const itk::CPRCenterlineStretch & s) { return p >= s.First && p <= s.Last; });
    };
    double drawn = 0.0; // pixels along the hidden stretches, for the dashes
    for (std::size_t i = 0; i + 1 < branch.Points.size(); ++i)
    {
      const auto   a = view.ToView(branch.Points[i]);
      const auto   b = view.ToView(branch.Points[i + 1]);
      const double length = std::hypot(b.Column - a.Column, b.Row - a.Row);
      const auto   steps = static_cast<long>(std::ceil(4.0 * length)) + 1;
      for (long k = 0; k <= steps; ++k)
      {
        const double t = static_cast<double>(k) / steps;
        const bool   hidden = hiddenAt(static_cast<double>(i) + t);
        if (hidden)
        {
          drawn += length / steps;
          if (std::fmod(drawn, 6.0) >= 3.0)
          {
            continue;
          }
        }
        Plot(image,
             std::lround(a.Column + t * (b.Column - a.Column)),
             std::lround(a.Row + t * (b.Row - a.Row)),
             PaletteColor(branch.Id, hidden));
      }
    }
  }
}

ReformationOutputs
WriteVisibilityFigure(VesselReformationLogic &    logic,
                      ReformationParameters       parameters,
                      const itk::CenterlineTree & tree,
                      const std::string &         phantomName,
                      double                      window,
                      double                      level,
                      const std::string &         path)
{
  struct Run
  {
    FloatImage2DType::Pointer CPR;
    FloatImage2DType::Pointer Depth;
    ReformationOutputs        Outputs;
  };
  const auto run = [&](itk::CPRDepthMode mode)
  {
    parameters.Mode = mode;
    logic.SetParameters(parameters);
    const ReformationOutputs & outputs = logic.Update();
    return Run{ ConvertVolumeNodeToDepthImage(outputs.CPR),
                ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth),
                outputs };
  };
  const Run                    scanline = run(itk::CPRDepthMode::Scanline);
  const Run                    visibility = run(itk::CPRDepthMode::Visibility);
  const itk::CPRViewGeometry & view = visibility.Outputs.View;

  const auto scanlineCPR = RenderWindowLevel(scanline.CPR, window, level);
  const auto visibilityCPR = RenderWindowLevel(visibility.CPR, window, level);
  DrawCenterlines(scanlineCPR, tree, view, {});
  DrawCenterlines(visibilityCPR, tree, view, visibility.Outputs.BranchOcclusions);
  const auto * values = scanline.Depth->GetBufferPointer();
  const auto   count = scanline.Depth->GetBufferedRegion().GetNumberOfPixels();
  const double nearest = *std::min_element(values, values + count);
  const double farthest = *std::max_element(values, values + count);
  const auto   size = view.GetSize();

  // The detail: where the most pixels have a vessel hidden behind the visible one.
  const auto         hidden = ConvertVolumeNodeToLabelImage(visibility.Outputs.HiddenLabels);
  const unsigned int detailWidth = static_cast<unsigned int>(0.3 * size[0]);
  const unsigned int detailHeight = static_cast<unsigned int>(0.2 * size[1]);
  const auto         corner = BusiestWindow(hidden, detailWidth, detailHeight);
  const unsigned int panelWidth = static_cast<unsigned int>(size[0]);
  const auto         detail = [&](const RGBImageType * image)
  { return Magnify(Crop(image, corner[0], corner[1], detailWidth, detailHeight), panelWidth); };

  double hiddenLength = 0.0;
  double length = 0.0;
  for (const auto & row : visibility.Outputs.BranchOcclusions)
  {
    hiddenLength += row.HiddenLength;
    length += row.Length;
  }
  std::ostringstream caption;
  caption.precision(3);
  caption << "Synthetic " << phantomName << " CTA at " << view.GetAngleInDegrees() << " degrees, relaxed ("
          << DescribeFilterSettings(parameters) << "). Dashed: centerline behind another vessel ("
          << std::lround(hiddenLength) << " of " << std::lround(length) << " mm).";
  const auto figure =
    ComposeFigure({ { { scanlineCPR, "scanline mpCPR" }, { visibilityCPR, "visibility" } },
                    { { RenderDepth(scanline.Depth, nearest, farthest), "depth, scanline" },
                      { RenderDepth(visibility.Depth, nearest, farthest), "depth, visibility" } },
                    { { RenderDepthColorBar(nearest, farthest, size[0]), "" } },
                    { { detail(scanlineCPR), "detail, scanline" }, { detail(visibilityCPR), "detail, visibility" } } },
                  caption.str());
  WriteRGBPNG(figure, path);
  return visibility.Outputs;
}
} // namespace vr
