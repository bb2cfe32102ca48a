// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrFigure.h"

#include "itkImageFileWriter.h"
#include "itkPNGImageIOFactory.h"
#include "vrAtomicOutput.h"
#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrWindowLevel.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace vr
{
namespace
{
const RGBPixelType Background = []
{
  RGBPixelType pixel;
  pixel.Set(20, 20, 24);
  return pixel;
}();

RGBImageType::Pointer
MakeRGBImage(unsigned int width, unsigned int height, const RGBPixelType & fill)
{
  auto                     image = RGBImageType::New();
  RGBImageType::RegionType region;
  region.SetSize({ { width, height } });
  image->SetRegions(region);
  image->Allocate();
  image->FillBuffer(fill);
  return image;
}

/** Viridis, sampled at nine points (matplotlib's, CC0). */
RGBPixelType
Viridis(double t)
{
  static const std::array<std::array<double, 3>, 9> table = { { { 68, 1, 84 },
                                                                { 71, 44, 122 },
                                                                { 59, 81, 139 },
                                                                { 44, 113, 142 },
                                                                { 33, 144, 141 },
                                                                { 39, 173, 129 },
                                                                { 92, 200, 99 },
                                                                { 170, 220, 50 },
                                                                { 253, 231, 37 } } };
  t = std::min(1.0, std::max(0.0, t)) * (table.size() - 1);
  const auto   k = std::min<std::size_t>(static_cast<std::size_t>(t), table.size() - 2);
  const double f = t - k;
  RGBPixelType pixel;
  for (unsigned int c = 0; c < 3; ++c)
  {
    pixel[c] = static_cast<unsigned char>(std::lround(table[k][c] + f * (table[k + 1][c] - table[k][c])));
  }
  return pixel;
}

/** Draws \a text in white with its top-left corner at (x, y), blending by the glyphs' coverage. */
void
DrawText(RGBImageType * image, const std::string & text, long x, long y, int fontSize)
{
  vtkTextRenderer * renderer = vtkTextRenderer::GetInstance();
  if (renderer == nullptr || text.empty())
  {
    return; // no FreeType: a figure without titles is still a figure
  }
  vtkNew<vtkTextProperty> property;
  property->SetFontSize(fontSize);
  property->SetColor(1.0, 1.0, 1.0);
  property->SetFontFamilyToArial();
  vtkNew<vtkImageData> glyphs;
  int                  dimensions[2] = { 0, 0 };
  if (!renderer->RenderString(property, vtkStdString(text), glyphs, dimensions, 72))
  {
    return;
  }
  int extent[6];
  glyphs->GetExtent(extent);
  const int    glyphWidth = extent[1] - extent[0] + 1;
  const int    glyphHeight = extent[3] - extent[2] + 1;
  const auto   size = image->GetLargestPossibleRegion().GetSize();
  const auto * rgba = static_cast<const unsigned char *>(glyphs->GetScalarPointer());
  for (int row = 0; row < glyphHeight; ++row)
  {
    const long targetRow = y + (glyphHeight - 1 - row); // VTK images run bottom-up
    if (targetRow < 0 || targetRow >= static_cast<long>(size[1]))
    {
      continue;
    }
    for (int column = 0; column < glyphWidth; ++column)
    {
      const long targetColumn = x + column;
      if (targetColumn < 0 || targetColumn >= static_cast<long>(size[0]))
      {
        continue;
      }
      const unsigned char * source = rgba + 4 * (static_cast<std::size_t>(row) * glyphWidth + column);
      const double          alpha = source[3] / 255.0;
      if (alpha <= 0.0)
      {
        continue;
      }
      RGBImageType::IndexType index = { { targetColumn, targetRow } };
      RGBPixelType            pixel = image->GetPixel(index);
      for (unsigned int c = 0; c < 3; ++c)
      {
        pixel[c] = static_cast<unsigned char>(std::lround(pixel[c] * (1.0 - alpha) + source[c] * alpha));
      }
      image->SetPixel(index, pixel);
    }
  }
}

void
Paste(RGBImageType * target, const RGBImageType * source, long x, long y)
{
  const auto size = source->GetLargestPossibleRegion().GetSize();
  for (unsigned int row = 0; row < size[1]; ++row)
  {
    for (unsigned int column = 0; column < size[0]; ++column)
    {
      RGBImageType::IndexType from = { { column, row } };
      RGBImageType::IndexType to = { { x + column, y + row } };
      target->SetPixel(to, source->GetPixel(from));
    }
  }
}

std::string
Millimetres(double value)
{
  std::ostringstream stream;
  stream << std::fixed << std::setprecision(0) << value << " mm";
  return stream.str();
}

constexpr int  TitleFontSize = 20;
constexpr long TitleHeight = 34;
constexpr long Gap = 16;
} // namespace

RGBImageType::Pointer
RenderWindowLevel(const FloatImage2DType * image, double window, double level)
{
  if (!(window > 0.0) || !std::isfinite(window) || !std::isfinite(level))
  {
    throw InputError("window/level " + std::to_string(window) + "/" + std::to_string(level) +
                     ": the window must be a finite number > 0 and the level finite");
  }
  const auto size = image->GetLargestPossibleRegion().GetSize();
  auto       rgb = MakeRGBImage(size[0], size[1], Background);
  const auto count = image->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    const unsigned char grey = WindowLevelToByte(image->GetBufferPointer()[k], window, level);
    rgb->GetBufferPointer()[k].Set(grey, grey, grey);
  }
  return rgb;
}

RGBImageType::Pointer
RenderDepth(const FloatImage2DType * depth, double nearest, double farthest)
{
  const auto   size = depth->GetLargestPossibleRegion().GetSize();
  auto         rgb = MakeRGBImage(size[0], size[1], Background);
  const auto   count = depth->GetBufferedRegion().GetNumberOfPixels();
  const double range = farthest > nearest ? farthest - nearest : 1.0;
  for (std::size_t k = 0; k < count; ++k)
  {
    rgb->GetBufferPointer()[k] = Viridis((depth->GetBufferPointer()[k] - nearest) / range);
  }
  return rgb;
}

RGBImageType::Pointer
RenderDepthRelief(const FloatImage2DType * depth, double nearest, double farthest)
{
  auto          rgb = RenderDepth(depth, nearest, farthest);
  const auto    size = depth->GetLargestPossibleRegion().GetSize();
  const auto &  spacing = depth->GetSpacing();
  const long    width = static_cast<long>(size[0]);
  const long    height = static_cast<long>(size[1]);
  const float * values = depth->GetBufferPointer();
  auto          at = [&](long column, long row)
  {
    column = std::min(width - 1, std::max(0L, column));
    row = std::min(height - 1, std::max(0L, row));
    return static_cast<double>(values[row * width + column]);
  };
  // Lambertian shading of the surface z = -depth (nearer is higher), light from the upper left.
  const double light[3] = { -0.5, -0.5, 0.7071 };
  for (long row = 0; row < height; ++row)
  {
    for (long column = 0; column < width; ++column)
    {
      const double dx = -(at(column + 1, row) - at(column - 1, row)) / (2.0 * spacing[0]);
      const double dy = -(at(column, row + 1) - at(column, row - 1)) / (2.0 * spacing[1]);
      const double norm = std::sqrt(dx * dx + dy * dy + 1.0);
      const double lambert = (-dx * light[0] - dy * light[1] + light[2]) / norm;
      const double shade = std::min(1.2, std::max(0.25, 0.35 + 0.85 * lambert));
      auto &       pixel = rgb->GetBufferPointer()[row * width + column];
      for (unsigned int c = 0; c < 3; ++c)
      {
        pixel[c] = static_cast<unsigned char>(std::min(255.0, pixel[c] * shade));
      }
    }
  }
  return rgb;
}

RGBImageType::Pointer
Crop(const RGBImageType * image, unsigned int x, unsigned int y, unsigned int width, unsigned int height)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  x = std::min<unsigned int>(x, size[0] - 1);
  y = std::min<unsigned int>(y, size[1] - 1);
  width = std::min<unsigned int>(width, size[0] - x);
  height = std::min<unsigned int>(height, size[1] - y);
  auto part = MakeRGBImage(width, height, Background);
  for (unsigned int row = 0; row < height; ++row)
  {
    for (unsigned int column = 0; column < width; ++column)
    {
      part->SetPixel({ { column, row } }, image->GetPixel({ { x + column, y + row } }));
    }
  }
  return part;
}

RGBImageType::Pointer
Magnify(const RGBImageType * image, unsigned int width)
{
  const auto         size = image->GetLargestPossibleRegion().GetSize();
  const double       scale = static_cast<double>(width) / size[0];
  const unsigned int height = std::max(1u, static_cast<unsigned int>(std::lround(size[1] * scale)));
  auto               magnified = MakeRGBImage(width, height, Background);
  for (unsigned int row = 0; row < height; ++row)
  {
    const auto sourceRow = std::min<unsigned int>(size[1] - 1, static_cast<unsigned int>(row / scale));
    for (unsigned int column = 0; column < width; ++column)
    {
      const auto sourceColumn = std::min<unsigned int>(size[0] - 1, static_cast<unsigned int>(column / scale));
      magnified->SetPixel({ { column, row } }, image->GetPixel({ { sourceColumn, sourceRow } }));
    }
  }
  return magnified;
}

std::pair<double, double>
RangeWithin(const FloatImage2DType * image,
            unsigned int             x,
            unsigned int             y,
            unsigned int             width,
            unsigned int             height,
            double                   low,
            double                   high)
{
  const auto          size = image->GetLargestPossibleRegion().GetSize();
  std::vector<double> values;
  for (unsigned int row = y; row < std::min<unsigned int>(y + height, size[1]); ++row)
  {
    for (unsigned int column = x; column < std::min<unsigned int>(x + width, size[0]); ++column)
    {
      values.push_back(image->GetPixel({ { column, row } }));
    }
  }
  if (values.empty())
  {
    return { 0.0, 1.0 };
  }
  std::sort(values.begin(), values.end());
  auto at = [&](double fraction)
  { return values[static_cast<std::size_t>(std::min(1.0, std::max(0.0, fraction)) * (values.size() - 1))]; };
  return { at(low), at(high) };
}

RGBImageType::Pointer
RenderDepthColorBar(double nearest, double farthest, unsigned int width)
{
  const unsigned int barHeight = 16;
  auto               bar = MakeRGBImage(width, barHeight + TitleHeight, Background);
  for (unsigned int column = 0; column < width; ++column)
  {
    const RGBPixelType colour = Viridis(width > 1 ? static_cast<double>(column) / (width - 1) : 0.0);
    for (unsigned int row = 0; row < barHeight; ++row)
    {
      bar->SetPixel({ { column, row } }, colour);
    }
  }
  DrawText(bar, "near " + Millimetres(nearest), 0, barHeight + 4, 16);
  DrawText(bar, "depth along the view", static_cast<long>(width) / 2 - 80, barHeight + 4, 16);
  DrawText(bar, Millimetres(farthest) + " far", static_cast<long>(width) - 90, barHeight + 4, 16);
  return bar;
}

RGBImageType::Pointer
ComposeFigure(const std::vector<std::vector<FigurePanel>> & rows, const std::string & caption)
{
  long              width = 0;
  long              height = Gap;
  std::vector<long> rowHeights;
  for (const auto & row : rows)
  {
    long rowWidth = Gap;
    long rowHeight = 0;
    for (const auto & panel : row)
    {
      const auto size = panel.Image->GetLargestPossibleRegion().GetSize();
      rowWidth += static_cast<long>(size[0]) + Gap;
      rowHeight = std::max(rowHeight, static_cast<long>(size[1]));
    }
    width = std::max(width, rowWidth);
    rowHeights.push_back(rowHeight + TitleHeight);
    height += rowHeight + TitleHeight + Gap;
  }
  height += caption.empty() ? 0 : TitleHeight;
  auto figure = MakeRGBImage(static_cast<unsigned int>(width), static_cast<unsigned int>(height), Background);
  long y = Gap;
  for (std::size_t r = 0; r < rows.size(); ++r)
  {
    long x = Gap;
    for (const auto & panel : rows[r])
    {
      DrawText(figure, panel.Title, x, y + 4, TitleFontSize);
      Paste(figure, panel.Image, x, y + TitleHeight);
      x += static_cast<long>(panel.Image->GetLargestPossibleRegion().GetSize()[0]) + Gap;
    }
    y += rowHeights[r] + Gap;
  }
  DrawText(figure, caption, Gap, y, 16);
  return figure;
}

void
WriteRGBPNG(const RGBImageType * image, const std::string & path)
{
  itk::PNGImageIOFactory::RegisterOneFactory();
  AtomicOutput output(path);
  auto         writer = itk::ImageFileWriter<RGBImageType>::New();
  writer->SetInput(image);
  writer->SetFileName(output.TemporaryPath());
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError("output " + path + ": could not write the PNG (" + error.GetDescription() + ")");
  }
  output.Commit();
}
} // namespace vr
