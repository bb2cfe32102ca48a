// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrText.h"
#include "vrCenterlinePolyData.h"
#include "vrCheckedXMLPolyDataReader.h"
#include "vrInputError.h"
#include "vrText.h"
#include "vrLegacyVTKReader.h"
#include "vrVTKErrorCapture.h"

#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <cctype>

namespace vr::detail
{
namespace
{
/** 3D Slicer writes "SPACE=RAS" or "SPACE=LPS" into the legacy header line (vtkMRMLModelStorageNode). */
CoordinateSpace
SpaceFromLegacyHeader(const char * header)
{
  const std::string text = header == nullptr ? std::string() : std::string(header);
  if (text.find("SPACE=LPS") != std::string::npos)
  {
    return CoordinateSpace::LPS;
  }
  if (text.find("SPACE=RAS") != std::string::npos)
  {
    return CoordinateSpace::RAS;
  }
  return CoordinateSpace::Auto;
}
/** An attribute of \a element as a whole number in [low, high]; \a fallback when absent. */
long long
WholeAttribute(vtkXMLDataElement * element,
               const char *        name,
               long long           low,
               long long           high,
               long long           fallback,
               const std::string & where)
{
  const char * text = element->GetAttribute(name);
  if (text == nullptr)
  {
    return fallback;
  }
  long long value = 0;
  if (!ParseWholeInteger(Trim(text), value) || value < low || value > high)
  {
    throw InputError(where + ": " + std::string(element->GetName() ? element->GetName() : "element") + " " + name +
                     "=\"" + std::string(text).substr(0, 20) + "\" must be a whole number from " + std::to_string(low) +
                     " to " + std::to_string(high));
  }
  return value;
}

/** Decodes base64 text (stops at the first character that is not base64 or at '='). */
std::string
DecodeBase64(const std::string & text, std::size_t characters)
{
  std::string  bytes;
  unsigned int buffer = 0;
  int          bits = 0;
  for (std::size_t k = 0; k < characters && k < text.size(); ++k)
  {
    const char   c = text[k];
    const char * alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char * at = c == '\0' ? nullptr : std::strchr(alphabet, c);
    if (at == nullptr)
    {
      break;
    }
    buffer = (buffer << 6) | static_cast<unsigned int>(at - alphabet);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      bytes.push_back(static_cast<char>((buffer >> bits) & 0xFF));
    }
  }
  return bytes;
}

/** The little- or big-endian unsigned integer of \a size bytes at \a at in \a bytes. */
std::uint64_t
HeaderInteger(const std::string & bytes, std::size_t at, std::size_t size, bool bigEndian)
{
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < size; ++b)
  {
    const auto byte = static_cast<unsigned char>(bytes[at + (bigEndian ? b : size - 1 - b)]);
    value = (value << 8) | byte;
  }
  return value;
}

/** Checks the size header VTK writes before an array's binary data (inline base64, or appended raw or base64), as
 * VTK's parser will trust it: uncompressed, one integer, the byte count; compressed, the block count, the block
 * size, the last block's size and each block's compressed size. Every size must fit in what the file holds after
 * it: VTK 9.1 allocates a block of the declared compressed size before reading it (fuzzing found a header asking
 * for 2.6 GB). \return the bytes of the array's values, uncompressed. */
std::uint64_t
CheckBinaryHeader(const std::string & file,
                  std::size_t         start,
                  bool                base64,
                  std::size_t         integerSize,
                  bool                bigEndian,
                  bool                compressed,
                  const std::string & where)
{
  if (start > file.size())
  {
    throw InputError(where + ": binary data starts beyond the end of the file");
  }
  std::string text;
  if (base64)
  {
    std::size_t end = start;
    while (end < file.size() && (std::isalnum(static_cast<unsigned char>(file[end])) || file[end] == '+' ||
                                 file[end] == '/' || file[end] == '='))
    {
      ++end;
    }
    text = file.substr(start, end - start);
  }
  const auto headerBytes = [&](std::size_t count) -> std::string
  {
    if (!base64)
    {
      return start + count <= file.size() ? file.substr(start, count) : std::string();
    }
    return DecodeBase64(text, (count + 2) / 3 * 4);
  };
  const std::size_t available = base64 ? text.size() / 4 * 3 + 3 : file.size() - start;
  if (!compressed)
  {
    const std::string header = headerBytes(integerSize);
    if (header.size() < integerSize || HeaderInteger(header, 0, integerSize, bigEndian) > available)
    {
      throw InputError(where + ": a binary array declares more bytes than the file holds");
    }
    return HeaderInteger(header, 0, integerSize, bigEndian);
  }
  std::string header = headerBytes(3 * integerSize);
  if (header.size() < 3 * integerSize)
  {
    throw InputError(where + ": a compressed array's header is cut off");
  }
  const std::uint64_t     blocks = HeaderInteger(header, 0, integerSize, bigEndian);
  const std::uint64_t     blockSize = HeaderInteger(header, integerSize, integerSize, bigEndian);
  const std::uint64_t     lastBlockSize = HeaderInteger(header, 2 * integerSize, integerSize, bigEndian);
  constexpr std::uint64_t MaximumBlocks = 1 << 20;
  constexpr std::uint64_t MaximumBlockSize = 1 << 26;
  if (blocks > MaximumBlocks || blockSize > MaximumBlockSize || lastBlockSize > blockSize ||
      blocks * blockSize > 1000000000)
  {
    throw InputError(where + ": a compressed array declares " + std::to_string(blocks) + " blocks of " +
                     std::to_string(blockSize) + " bytes, more than this reader accepts");
  }
  const std::size_t headerSize = (3 + static_cast<std::size_t>(blocks)) * integerSize;
  header = headerBytes(headerSize);
  if (header.size() < headerSize)
  {
    throw InputError(where + ": a compressed array's header is cut off");
  }
  std::uint64_t compressedTotal = 0;
  for (std::size_t b = 0; b < blocks; ++b)
  {
    compressedTotal += HeaderInteger(header, (3 + b) * integerSize, integerSize, bigEndian);
    if (compressedTotal > available)
    {
      throw InputError(where + ": a compressed array declares more compressed bytes than the file holds");
    }
  }
  // Every block is full but the last, whose size is given unless it is full too (0).
  return blocks == 0 ? 0 : (blocks - 1) * blockSize + (lastBlockSize == 0 ? blockSize : lastBlockSize);
}

/** Bytes of one value of an XML data array type; 0 for strings and types this check does not count. */
std::size_t
XMLTypeSize(const char * type)
{
  const std::string t = type == nullptr ? std::string() : std::string(type);
  if (t == "Int8" || t == "UInt8" || t == "Char")
  {
    return 1;
  }
  if (t == "Int16" || t == "UInt16")
  {
    return 2;
  }
  if (t == "Int32" || t == "UInt32" || t == "Float32")
  {
    return 4;
  }
  if (t == "Int64" || t == "UInt64" || t == "Float64")
  {
    return 8;
  }
  return 0;
}

/** Whitespace-separated values of inline ASCII data from \a start up to the next tag. */
long long
CountASCIIValues(const std::string & file, std::size_t start)
{
  long long count = 0;
  bool      inValue = false;
  for (std::size_t k = start; k < file.size() && file[k] != '<'; ++k)
  {
    const bool space = std::isspace(static_cast<unsigned char>(file[k])) != 0;
    count += !space && !inValue ? 1 : 0;
    inValue = !space;
  }
  return count;
}

/** Checks the parsed XML of a .vtp before VTK's reader reads its arrays: VTK 9.1 trusts the declared counts and
 * component numbers (Points of 6 components make it leak the points it read; negative or huge counts size its
 * buffers). Every Piece's counts, the Points array's 3 components, and every data array's 1 to 64 components; the
 * values each array of numbers holds (counted in the file: ASCII values, the byte count of binary data) against what
 * the piece needs: 3 per point, the points or cells times the components for point and cell data, one offset per
 * cell. \return the values each such array holds, for the checks made while VTK reads the cells. */
ValuesHeld
CheckVTPStructure(vtkXMLDataParser * parser, const std::string & path, const std::string & where)
{
  constexpr long long MaximumCount = 10000000;
  vtkXMLDataElement * root = parser != nullptr ? parser->GetRootElement() : nullptr;
  if (root == nullptr || root->GetName() == nullptr || std::string(root->GetName()) != "VTKFile")
  {
    throw InputError(where + ": not a VTK XML file (no VTKFile element)");
  }
  const char * type = root->GetAttribute("type");
  if (type == nullptr || std::string(type) != "PolyData")
  {
    throw InputError(where + ": VTKFile type is not PolyData");
  }
  const char *      headerType = root->GetAttribute("header_type");
  const std::size_t integerSize = headerType != nullptr && std::string(headerType) == "UInt64" ? 8 : 4;
  const char *      byteOrder = root->GetAttribute("byte_order");
  const bool        bigEndian = byteOrder != nullptr && std::string(byteOrder) == "BigEndian";
  const bool        compressed = root->GetAttribute("compressor") != nullptr;
  std::string       file;
  {
    std::ifstream input(path, std::ios::binary);
    file.assign(std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>());
  }
  // Appended data: where it starts, and whether it is raw or base64.
  bool                appendedBase64 = true;
  vtkXMLDataElement * appended = root->FindNestedElementWithName("AppendedData");
  if (appended != nullptr && appended->GetAttribute("encoding") != nullptr)
  {
    appendedBase64 = std::string(appended->GetAttribute("encoding")) != "raw";
  }
  std::size_t appendedStart = file.size();
  if (appended != nullptr && parser->GetAppendedDataPosition() > 0)
  {
    appendedStart = static_cast<std::size_t>(parser->GetAppendedDataPosition());
  }
  else if (appended != nullptr)
  {
    const auto marker =
      file.find('_', static_cast<std::size_t>(std::max<vtkTypeInt64>(0, appended->GetXMLByteIndex())));
    appendedStart = marker == std::string::npos ? file.size() : marker + 1;
  }
  ValuesHeld held;
  for (int d = 0; d < root->GetNumberOfNestedElements(); ++d)
  {
    vtkXMLDataElement * dataSet = root->GetNestedElement(d);
    if (dataSet->GetName() == nullptr || std::string(dataSet->GetName()) != "PolyData")
    {
      continue;
    }
    for (int p = 0; p < dataSet->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement * piece = dataSet->GetNestedElement(p);
      if (piece->GetName() == nullptr || std::string(piece->GetName()) != "Piece")
      {
        continue;
      }
      std::map<std::string, long long> counts;
      for (const char * count :
           { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
      {
        counts[count] = WholeAttribute(piece, count, 0, MaximumCount, 0, where);
      }
      const long long cells =
        counts["NumberOfVerts"] + counts["NumberOfLines"] + counts["NumberOfStrips"] + counts["NumberOfPolys"];
      for (int s = 0; s < piece->GetNumberOfNestedElements(); ++s)
      {
        vtkXMLDataElement * section = piece->GetNestedElement(s);
        const std::string   sectionName = section->GetName() ? section->GetName() : "";
        for (int a = 0; a < section->GetNumberOfNestedElements(); ++a)
        {
          vtkXMLDataElement * array = section->GetNestedElement(a);
          if (array->GetName() == nullptr || std::string(array->GetName()) != "DataArray")
          {
            continue;
          }
          const long long components = WholeAttribute(array, "NumberOfComponents", 1, 64, 1, where);
          if (sectionName == "Points" && components != 3)
          {
            throw InputError(where + ": the Points array has " + std::to_string(components) +
                             " components; points have 3");
          }
          const long long tuples = WholeAttribute(array, "NumberOfTuples", 0, MaximumCount, 0, where);
          if (static_cast<double>(tuples) * static_cast<double>(components) > 3.0 * MaximumCount)
          {
            throw InputError(where + ": a data array of " + std::to_string(tuples) + " x " +
                             std::to_string(components) + " values is more than this reader accepts");
          }
          const std::string format = array->GetAttribute("format") ? array->GetAttribute("format") : "ascii";
          const std::size_t typeSize = XMLTypeSize(array->GetAttribute("type"));
          std::uint64_t     bytes = 0;
          if (format == "binary")
          {
            // The inline data follows the end of the DataArray's start tag (VTK keeps its own position protected).
            std::size_t start =
              file.find('>', static_cast<std::size_t>(std::max<vtkTypeInt64>(0, array->GetXMLByteIndex())));
            start = start == std::string::npos ? file.size() : start + 1;
            while (start < file.size() && std::isspace(static_cast<unsigned char>(file[start])))
            {
              ++start;
            }
            bytes = CheckBinaryHeader(file, start, true, integerSize, bigEndian, compressed, where);
          }
          else if (format == "appended")
          {
            const long long offset = WholeAttribute(array, "offset", 0, 1LL << 40, 0, where);
            bytes = CheckBinaryHeader(file,
                                      appendedStart + static_cast<std::size_t>(offset),
                                      appendedBase64,
                                      integerSize,
                                      bigEndian,
                                      compressed,
                                      where);
          }
          else if (format != "ascii")
          {
            throw InputError(where + ": data array format \"" + format.substr(0, 20) +
                             "\" is not ascii, binary or appended");
          }
          if (typeSize == 0)
          {
            continue;
          }
          long long values = static_cast<long long>(bytes / typeSize);
          if (format == "ascii")
          {
            const std::size_t start =
              file.find('>', static_cast<std::size_t>(std::max<vtkTypeInt64>(0, array->GetXMLByteIndex())));
            values = start == std::string::npos ? 0 : CountASCIIValues(file, start + 1);
          }
          held[array] = values;
          const char *      arrayName = array->GetAttribute("Name");
          const std::string name = arrayName != nullptr ? arrayName : "";
          long long         expected = -1;
          if (sectionName == "Points")
          {
            expected = 3 * counts["NumberOfPoints"];
          }
          else if (sectionName == "PointData")
          {
            expected = components * counts["NumberOfPoints"];
          }
          else if (sectionName == "CellData")
          {
            expected = components * cells;
          }
          else if (name == "offsets" && counts.count("NumberOf" + sectionName) != 0)
          {
            expected = counts["NumberOf" + sectionName];
          }
          if (expected >= 0 && values != expected)
          {
            throw InputError(where + ": the " + sectionName + " array \"" + name.substr(0, 40) + "\" holds " +
                             std::to_string(values) + " values; the piece's counts need " + std::to_string(expected));
          }
        }
      }
    }
  }
  return held;
}
} // namespace

itk::CenterlineTree
ReadVTKCenterlines(const std::string & path, CoordinateSpace space, CenterlineReadReport & report)
{
  vtkSmartPointer<vtkPolyData> polyData;
  CoordinateSpace              headerSpace = CoordinateSpace::Auto;
  {
    detail::VTKErrorCapture capture;
    if (HasExtension(path, ".vtp"))
    {
      report.Format = "VTK XML PolyData (.vtp)";
      auto reader = vtkSmartPointer<CheckedXMLPolyDataReader>::New();
      capture.Observe(reader);
      reader->SetFileName(path.c_str());
      // The XML first; its declarations are checked before the reader reads the arrays they describe.
      reader->UpdateInformation();
      if (capture.HasErrors())
      {
        throw InputError("centerline file " + path +
                         ": not a readable VTK XML PolyData file (truncated or corrupt?): " + capture.FirstError());
      }
      reader->SetValuesHeld(CheckVTPStructure(reader->GetXMLParser(), path, "centerline file " + path));
      reader->Update();
      if (!reader->Problem().empty())
      {
        throw InputError("centerline file " + path + ": " + reader->Problem());
      }
      if (capture.HasErrors())
      {
        throw InputError("centerline file " + path +
                         ": not a readable VTK XML PolyData file (truncated or corrupt?): " + capture.FirstError());
      }
      polyData = reader->GetOutput();
    }
    else
    {
      report.Format = "legacy VTK PolyData (.vtk)";
      // Our own reader: VTK's legacy reader trusts the file's counts.
      LegacyVTKPolyData legacy = ReadLegacyVTKPolyData(path, "centerline file " + path);
      headerSpace = SpaceFromLegacyHeader(legacy.Header.c_str());
      polyData = legacy.PolyData;
    }
  }
  if (polyData == nullptr || polyData->GetNumberOfPoints() == 0)
  {
    throw InputError("centerline file " + path + ": holds no point");
  }

  const std::string format = report.Format;
  CoordinateSpace   used = space;
  std::string       source = "override";
  if (space == CoordinateSpace::Auto && headerSpace != CoordinateSpace::Auto)
  {
    used = headerSpace;
    source = std::string("SPACE=") + ToString(headerSpace) + " in the file header";
  }
  itk::CenterlineTree tree = CenterlineTreeFromPolyData(polyData, used, "centerline file " + path, &report);
  report.Format = format;
  if (used != CoordinateSpace::Auto)
  {
    report.SpaceSource = source;
  }
  else if (report.SpaceSource == "SPACE field data")
  {
    report.SpaceSource = "SPACE field data in the file";
  }
  else
  {
    report.SpaceSource = "no SPACE in the file: RAS, the VMTK and 3D Slicer convention";
  }
  return tree;
}

void
WriteVTKCenterlines(const itk::CenterlineTree & tree,
                    const std::string &         finalPath,
                    const std::string &         temporaryPath,
                    CoordinateSpace             space)
{
  const CoordinateSpace        used = space == CoordinateSpace::LPS ? CoordinateSpace::LPS : CoordinateSpace::RAS;
  vtkSmartPointer<vtkPolyData> polyData = PolyDataFromCenterlineTree(tree, used);
  // The radius under VMTK's name as well as 3D Slicer's: vmtk scripts (vmtkcenterlineresampling,
  // vmtkbranchextractor, ...) look for MaximumInscribedSphereRadius, 3D Slicer for Radius.
  if (vtkDataArray * radius = polyData->GetPointData()->GetArray(SlicerRadiusArrayName))
  {
    auto vmtkRadius = vtkSmartPointer<vtkDoubleArray>::New();
    vmtkRadius->DeepCopy(radius);
    vmtkRadius->SetName(VMTKRadiusArrayName);
    polyData->GetPointData()->AddArray(vmtkRadius);
  }
  detail::VTKErrorCapture capture;
  int                     written = 0;
  if (HasExtension(finalPath, ".vtp"))
  {
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    capture.Observe(writer);
    writer->SetInputData(polyData);
    writer->SetFileName(temporaryPath.c_str());
    writer->SetDataModeToBinary();
    written = writer->Write();
  }
  else
  {
    auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
    capture.Observe(writer);
    writer->SetInputData(polyData);
    writer->SetFileName(temporaryPath.c_str());
    // Version 4.2 is what 3D Slicer writes: VMTK and VTK < 9 cannot read 5.1.
    writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    writer->SetFileTypeToBinary();
    const std::string header = std::string("VesselReformation centerlines. SPACE=") + ToString(used);
    writer->SetHeader(header.c_str());
    written = writer->Write();
  }
  if (written == 0 || capture.HasErrors())
  {
    throw InputError("centerline output " + finalPath + ": could not be written: " +
                     (capture.HasErrors() ? capture.FirstError() : std::string("the VTK writer failed")));
  }
}
} // namespace vr::detail
