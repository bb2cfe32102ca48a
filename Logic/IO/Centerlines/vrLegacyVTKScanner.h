// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLegacyVTKScanner_h
#define vrLegacyVTKScanner_h

#include <vtkSmartPointer.h>

#include <cstddef>
#include <string>
#include <vector>

class vtkAbstractArray;
class vtkDataArray;
class vtkStringArray;

namespace vr::detail
{
/** A cursor over the whole of a legacy .vtk file: keyword lines, and the data blocks between them (ASCII or
 * big-endian binary values, strings, the METADATA block VTK may write after an array). It knows the format's
 * tokens, not its sections: ReadLegacyVTKPolyData (vrLegacyVTKReader.h) reads those with it. Every problem is a
 * vr::InputError "<where>: <what is wrong> (legacy VTK, line N)". */
class LegacyVTKScanner
{
public:
  /** Values of one array and components of one tuple this scanner accepts: a centerline file holds thousands of
   * points, so these only stop hostile counts before anything is allocated. */
  static constexpr long long   MaximumCount = 1LL << 30;
  static constexpr long long   MaximumComponents = 1024;
  static constexpr std::size_t MaximumWordLength = 255; // VTK reads keywords, names and types into 256 bytes

  /** A legacy data type: the VTK array it becomes and its size in a binary file. */
  struct DataType
  {
    int         VTKType{ 0 };
    std::size_t FileBytes{ 0 };
    bool        String{ false };
  };

  /** \a text is the whole file; \a where names it in messages ("centerline file x.vtk"). */
  LegacyVTKScanner(std::string text, std::string where);

  /** Throws the InputError for \a problem at the current position (on a line just read: that line). */
  [[noreturn]] void
  Fail(const std::string & problem) const;

  /** Whether the data blocks are binary (the file's third line says BINARY). */
  bool Binary{ false };

  /** Whether only white space remains. */
  bool
  AtEnd();

  /** The next line without its end (and without a '\r' before it); fails at the end of the file. */
  std::string
  Line();

  /** The words of the next line that is not blank; fails at the end of the file. */
  std::vector<std::string>
  Words();

  /** A count from a section line: a whole number from \a low to MaximumCount. */
  long long
  Count(const std::string & text, const std::string & what, long long low = 0) const;

  /** \a tuples x \a components values of the type named \a typeName, then the METADATA block VTK may write after
   * them. \a what names the array in messages. */
  vtkSmartPointer<vtkAbstractArray>
  Array(const std::string & typeName, long long tuples, long long components, const std::string & what);

  /** A name from a section line, %XX escapes decoded. */
  std::string
  Name(const std::string & text, const std::string & what) const;

private:
  std::size_t
  Remaining() const;

  void
  CheckRemaining(double bytes, long long count, const std::string & what) const;

  /** Big-endian values, right after the section line (VTK writes a newline after them). */
  void
  ReadBinary(vtkDataArray & array, const DataType & type, long long count);

  /** Whitespace-separated numbers, across lines; the rest of the last line must be blank. */
  template<typename T>
  void
  ReadAscii(T * out, long long count, const std::string & what);

  /** \a count strings: one a line, %XX-encoded (ASCII), or each after a length header whose top two bits say its
   * size (binary: 11 one byte, 10 two, 01 four, 00 eight; the rest of the header is the length, big-endian). */
  void
  ReadStrings(vtkStringArray & array, long long count, const std::string & what);

  /** VTK's %XX escapes (vtkDataWriter encodes spaces and unprintable characters so). */
  std::string
  Decode(const std::string & text, const std::string & what) const;

  void
  SkipNewline();

  /** The block VTK writes after an array with component names or information keys: "METADATA", then
   * "COMPONENT_NAMES" with one line per component and "INFORMATION n" with its key lines, up to a blank line. Its
   * content only decorates the array, so it is skipped; anything else there is refused. */
  void
  SkipMetaData(long long components);

  std::string m_Text;
  std::string m_Where;
  std::size_t m_At{ 0 };
};
} // namespace vr::detail

#endif
