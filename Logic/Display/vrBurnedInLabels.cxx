// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrBurnedInLabels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>

namespace vr
{
namespace
{
/** A 5 x 7 glyph: seven rows, the leftmost pixel in bit 4. */
using Glyph = std::array<unsigned char, 7>;

constexpr int GlyphWidth = 5;
constexpr int GlyphHeight = 7;
/** Font pixels between characters. */
constexpr int Spacing = 1;
/** The degree sign as this font takes it (UTF-8 "°" is two bytes; it is mapped to this one). */
constexpr char Degree = '\x01';

Glyph
GlyphOf(char c)
{
  switch (c)
  {
    case '0':
      return { 0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E };
    case '1':
      return { 0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E };
    case '2':
      return { 0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F };
    case '3':
      return { 0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E };
    case '4':
      return { 0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02 };
    case '5':
      return { 0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E };
    case '6':
      return { 0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E };
    case '7':
      return { 0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08 };
    case '8':
      return { 0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E };
    case '9':
      return { 0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C };
    case '.':
      return { 0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C };
    case '-':
      return { 0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00 };
    case '+':
      return { 0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00 };
    case Degree:
      return { 0x0C, 0x12, 0x12, 0x0C, 0x00, 0x00, 0x00 };
    case 'A':
      return { 0x0E, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11 };
    case 'I':
      return { 0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E };
    case 'L':
      return { 0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F };
    case 'P':
      return { 0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10 };
    case 'R':
      return { 0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11 };
    case 'S':
      return { 0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E };
    default:
      return { 0, 0, 0, 0, 0, 0, 0 };
  }
}

/** The text as the font's characters: UTF-8's degree sign becomes one. */
std::string
FontCharacters(const std::string & text)
{
  std::string characters;
  for (std::size_t k = 0; k < text.size(); ++k)
  {
    if (static_cast<unsigned char>(text[k]) == 0xC2 && k + 1 < text.size() &&
        static_cast<unsigned char>(text[k + 1]) == 0xB0)
    {
      characters += Degree;
      ++k;
    }
    else
    {
      characters += text[k];
    }
  }
  return characters;
}

/** Sets the \a scale x \a scale block of font pixel (column, row) at (x, y), grown by \a grow pixels, to \a value. */
void
Block(MaskImageType * image, long x, long y, int scale, int grow, unsigned char value)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  for (long j = y - grow; j < y + scale + grow; ++j)
  {
    for (long i = x - grow; i < x + scale + grow; ++i)
    {
      if (i >= 0 && j >= 0 && i < static_cast<long>(size[0]) && j < static_cast<long>(size[1]))
      {
        image->GetBufferPointer()[static_cast<std::size_t>(j) * size[0] + static_cast<std::size_t>(i)] = value;
      }
    }
  }
}
} // namespace

std::string
OrientationLetters(const itk::Vector<double, 3> & lps)
{
  static const char  positive[] = { 'L', 'P', 'S' };
  static const char  negative[] = { 'R', 'A', 'I' };
  std::array<int, 3> order = { 0, 1, 2 };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(lps[a]) > std::abs(lps[b]); });
  const double norm = lps.GetNorm();
  if (!(norm > 0.0))
  {
    return std::string();
  }
  std::string letters(1, lps[order[0]] > 0.0 ? positive[order[0]] : negative[order[0]]);
  if (std::abs(lps[order[1]]) / norm >= 0.4)
  {
    letters += lps[order[1]] > 0.0 ? positive[order[1]] : negative[order[1]];
  }
  return letters;
}

void
BurnedInTextSize(const std::string & text, int scale, long & width, long & height)
{
  const auto count = static_cast<long>(FontCharacters(text).size());
  width = count > 0 ? (count * (GlyphWidth + Spacing) - Spacing) * scale : 0;
  height = GlyphHeight * scale;
}

void
BurnInText(MaskImageType * image, const std::string & text, long x, long y, int scale)
{
  const std::string characters = FontCharacters(text);
  scale = std::max(1, scale);
  // The outline first, then the glyphs over it: white on black reads on any grey.
  for (const auto [grow, value] : { std::pair<int, unsigned char>{ 1, 0 }, std::pair<int, unsigned char>{ 0, 255 } })
  {
    long left = x;
    for (const char c : characters)
    {
      const Glyph glyph = GlyphOf(c);
      for (int row = 0; row < GlyphHeight; ++row)
      {
        for (int column = 0; column < GlyphWidth; ++column)
        {
          if (glyph[row] & (0x10 >> column))
          {
            Block(image, left + column * scale, y + row * scale, scale, grow, value);
          }
        }
      }
      left += (GlyphWidth + Spacing) * scale;
    }
  }
}

void
BurnInViewLabels(MaskImageType *                image,
                 const itk::Vector<double, 3> & screenRight,
                 const itk::Vector<double, 3> & screenUp,
                 double                         angleInDegrees)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  const long width = static_cast<long>(size[0]);
  const long height = static_cast<long>(size[1]);
  const int  scale = std::max(2, static_cast<int>(std::lround(std::max(width, height) / 170.0)));
  const long margin = 2 * scale;

  std::ostringstream angle;
  angle.precision(4);
  angle << (std::abs(angleInDegrees) < 5e-5 ? 0.0 : angleInDegrees) << "\xC2\xB0";
  BurnInText(image, angle.str(), margin, margin, scale);

  const auto place = [&](const itk::Vector<double, 3> & direction, int horizontal, int vertical)
  {
    const std::string letters = OrientationLetters(direction);
    long              w = 0;
    long              h = 0;
    BurnedInTextSize(letters, scale, w, h);
    const long x = horizontal < 0 ? margin : horizontal > 0 ? width - margin - w : (width - w) / 2;
    const long y = vertical < 0 ? margin : vertical > 0 ? height - margin - h : (height - h) / 2;
    BurnInText(image, letters, x, y, scale);
  };
  place(screenRight, 1, 0);
  place(-screenRight, -1, 0);
  place(screenUp, 0, -1);
  place(-screenUp, 0, 1);
}
} // namespace vr
