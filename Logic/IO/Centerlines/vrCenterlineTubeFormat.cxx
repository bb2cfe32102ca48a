// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrMetaIOWords.h"
#include "vrText.h"

#include "itkSpatialObjectReader.h"
#include "itkSpatialObjectWriter.h"

#include <algorithm>
#include <cctype>
#include <exception>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace vr::detail
{
namespace
{
/** The limits of the .tre subset this reader accepts. */
constexpr long long   MaximumTubeObjects = 100000;
constexpr long long   MaximumTubePoints = 10000000;
constexpr std::size_t MaximumPointFields = 64;

/** Bytes per value of a MetaIO ElementType, 0 for one MetaIO cannot hold in a tube point. */
std::size_t
ElementBytes(const std::string & type)
{
  static const std::pair<const char *, std::size_t> sizes[] = {
    { "MET_CHAR", 1 },  { "MET_UCHAR", 1 },  { "MET_SHORT", 2 },     { "MET_USHORT", 2 },
    { "MET_INT", 4 },   { "MET_UINT", 4 },   { "MET_LONG", 4 },      { "MET_ULONG", 4 },
    { "MET_FLOAT", 4 }, { "MET_DOUBLE", 8 }, { "MET_LONG_LONG", 8 }, { "MET_ULONG_LONG", 8 }
  };
  for (const auto & [name, bytes] : sizes)
  {
    if (type == name)
    {
      return bytes;
    }
  }
  return 0;
}

std::vector<std::string>
Tokens(const std::string & text)
{
  std::istringstream       stream(text);
  std::vector<std::string> tokens;
  std::string              token;
  while (stream >> token)
  {
    tokens.push_back(token);
  }
  return tokens;
}

/** Walks a .tre file the way MetaIO's scene reader will, checking every field MetaIO sizes arrays or reads with:
 * object types, NDims, NObjects, PointDim, ElementType, NPoints against limits and against the bytes that really
 * follow, and the length of every array field. MetaIO trusts them all: NDims beyond its fixed arrays overflows
 * them, a PointDim without x, y, z reads outside its point, and NPoints of two billion overflows its int byte count
 * or allocates a point object per declared point. Throws vr::InputError naming the file, the object and the
 * field. */
void
CheckTubeFile(const std::string & path)
{
  std::ifstream input(path, std::ios::binary);
  if (!input)
  {
    throw InputError("centerline file " + path + ": cannot be opened");
  }
  const std::string text((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>());
  std::size_t       at = 0;
  long long         objects = 0;
  long long         declaredObjects = -1; // the scene's NObjects
  std::string       type;
  long long         dimensions = 0;
  long long         points = -1;
  std::size_t       fields = 0;
  bool              hasXYZ = false;
  std::size_t       elementBytes = 4;
  bool              binary = false;
  std::string       where;
  const auto        fail = [&](const std::string & problem)
  { throw InputError("centerline file " + path + ": " + where + problem); };
  const auto wholeNumber = [&](const std::string & key, const std::string & value, long long low, long long high)
  {
    long long number = 0;
    if (!ParseWholeInteger(Trim(value), number) || number < low || number > high)
    {
      fail(key + " = " + Trim(value).substr(0, 40) + ": must be a whole number from " + std::to_string(low) + " to " +
           std::to_string(high));
    }
    return number;
  };
  while (at < text.size())
  {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos)
    {
      end = text.size();
    }
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    if (Trim(line).empty())
    {
      continue;
    }
    const auto equals = line.find('=');
    if (equals == std::string::npos)
    {
      fail("line \"" + Trim(line).substr(0, 40) + "\" is not \"Field = value\"; not a MetaIO .tre file");
    }
    // MetaIO reads the line after an ObjectType into 500 characters and takes what follows "= ": a line ending at its
    // "=", or longer than that buffer, makes it throw (fuzzing), leaking what it had read.
    if (equals + 1 >= line.size() || line.size() > 400)
    {
      fail("line \"" + Trim(line).substr(0, 40) + "\" has no value after its \"=\" or is over 400 characters");
    }
    // MetaIO copies string values into fixed 255-character fields without always ending them (fuzzing: a PointDim
    // of 300 bytes made MetaTube read past its field); header lines of a valid file are short printable ASCII.
    if (line.size() - equals - 1 > 200 ||
        std::any_of(line.begin(), line.end(), [](char c) { return (c < 0x20 && c != '\t' && c != '\r') || c > 0x7E; }))
    {
      fail("line \"" + Trim(line).substr(0, 20) +
           "...\" has a value over 200 characters or a character that is "
           "not printable ASCII");
    }
    const std::string key = Trim(line.substr(0, equals));
    const std::string value = line.substr(equals + 1);
    if (key == "ObjectType")
    {
      type = Trim(value);
      ++objects;
      where = "object " + std::to_string(objects) + " (" + type.substr(0, 20) + "): ";
      if (objects > MaximumTubeObjects)
      {
        fail("more than " + std::to_string(MaximumTubeObjects) + " objects");
      }
      if (type != "Scene" && type != "Group" && type != "Tube" && type != "VesselTube")
      {
        fail("ObjectType " + type.substr(0, 20) +
             " is not one of a centerline file's (Scene, Group, Tube, VesselTube)");
      }
      // MetaIO's scene reader fails on a second scene and leaks what it had read (fuzzing).
      if (type == "Scene" && objects != 1)
      {
        fail("a Scene may only be the file's first object");
      }
      dimensions = 0;
      points = -1;
      fields = 0;
      hasXYZ = false;
      elementBytes = 4;
      binary = false;
      continue;
    }
    if (type.empty())
    {
      fail("the file does not start with ObjectType; not a MetaIO .tre file");
    }
    if (key == "NDims")
    {
      dimensions = wholeNumber(key, value, 2, 3);
      if ((type == "Tube" || type == "VesselTube") && dimensions != 3)
      {
        fail("NDims = " + std::to_string(dimensions) + ": a centerline tube must be 3D");
      }
    }
    else if (key == "NObjects")
    {
      const long long count = wholeNumber(key, value, 0, MaximumTubeObjects);
      if (type == "Scene")
      {
        declaredObjects = count;
      }
    }
    else if (key == "ID" || key == "ParentID")
    {
      wholeNumber(key, value, -1, 2147483647);
    }
    else if (key == "BinaryData")
    {
      binary = Trim(value) == "True" || Trim(value) == "true" || Trim(value) == "1";
    }
    else if (key == "ElementType")
    {
      elementBytes = ElementBytes(Trim(value));
      if (elementBytes == 0)
      {
        fail("ElementType = " + Trim(value).substr(0, 20) + " is not a MetaIO number type");
      }
    }
    else if (key == "TransformMatrix" || key == "Offset" || key == "Position" || key == "Origin" ||
             key == "CenterOfRotation" || key == "ElementSpacing" || key == "Color" || key == "Orientation" ||
             key == "Rotation")
    {
      if (dimensions == 0)
      {
        fail(key + " comes before NDims");
      }
      const std::size_t square = static_cast<std::size_t>(dimensions * dimensions);
      const std::size_t wanted = key == "Color" ? 4
                                 : (key == "TransformMatrix" || key == "Orientation" || key == "Rotation")
                                   ? square
                                   : static_cast<std::size_t>(dimensions);
      const auto        tokens = Tokens(value);
      double            number = 0.0;
      if (tokens.size() != wanted || !std::all_of(tokens.begin(),
                                                  tokens.end(),
                                                  [&](const std::string & t) { return ParseWholeDouble(t, number); }))
      {
        fail(key + " must be " + std::to_string(wanted) + " finite numbers (NDims = " + std::to_string(dimensions) +
             ")");
      }
    }
    else if (key == "PointDim")
    {
      // The value MetaIO keeps (after the run of "=", ":" and blanks, without trailing blanks), split as MetaTube
      // splits it.
      const std::size_t first = value.find_first_not_of("=: \t");
      const auto        names = MetaIOWords(first == std::string::npos ? std::string() : Trim(value.substr(first)));
      if (names.empty())
      {
        fail("PointDim = " + Trim(value).substr(0, 40) +
             ": must be field names separated by single spaces, each of at most " +
             std::to_string(MaximumMetaIOWordLength) + " characters");
      }
      fields = names.size();
      if (fields > MaximumPointFields)
      {
        fail("PointDim names " + std::to_string(fields) + " fields; from 1 to " + std::to_string(MaximumPointFields) +
             " are accepted");
      }
      const auto has = [&](const char * name) { return std::find(names.begin(), names.end(), name) != names.end(); };
      hasXYZ = has("x") && has("y") && has("z");
    }
    else if (key == "NPoints")
    {
      points = wholeNumber(key, value, 0, 9223372036854775807LL);
    }
    else if (key == "Points")
    {
      if (type != "Tube" && type != "VesselTube")
      {
        fail("Points in an object that is not a tube");
      }
      if (dimensions != 3 || fields == 0 || points < 0)
      {
        fail("Points before NDims, PointDim and NPoints");
      }
      if (!hasXYZ)
      {
        fail("PointDim lacks x, y or z; a tube point needs its position");
      }
      const std::size_t remaining = text.size() - std::min(at, text.size());
      const double perPoint = binary ? static_cast<double>(fields * elementBytes) : 2.0 * static_cast<double>(fields);
      const double needed = static_cast<double>(points) * perPoint;
      if (points > MaximumTubePoints || needed > static_cast<double>(remaining) + 1.0)
      {
        fail("NPoints = " + std::to_string(points) + " needs at least " +
             std::to_string(static_cast<long long>(needed)) + " bytes of point data, but " + std::to_string(remaining) +
             " follow" +
             (points > MaximumTubePoints ? " (and at most " + std::to_string(MaximumTubePoints) + " are accepted)"
                                         : std::string()));
      }
      if (binary)
      {
        at += static_cast<std::size_t>(needed);
      }
      else
      {
        // Skip the point values, number by number.
        std::size_t values = static_cast<std::size_t>(points) * fields;
        while (values > 0 && at < text.size())
        {
          while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])))
          {
            ++at;
          }
          const std::size_t start = at;
          while (at < text.size() && !std::isspace(static_cast<unsigned char>(text[at])))
          {
            ++at;
          }
          double number = 0.0;
          if (!ParseWholeDouble(text.substr(start, at - start), number))
          {
            fail("point value \"" + text.substr(start, std::min<std::size_t>(at - start, 20)) +
                 "\" is not a finite number");
          }
          --values;
        }
        if (values > 0)
        {
          fail("NPoints = " + std::to_string(points) + " but the file ends before all points");
        }
      }
    }
  }
  if (objects == 0)
  {
    fail("no ObjectType; not a MetaIO .tre file");
  }
  // A scene holding other than the objects it declares makes MetaIO's reader fail part-way, leaking what it read.
  if (declaredObjects >= 0 && objects - 1 != declaredObjects)
  {
    where.clear();
    fail("the scene declares NObjects = " + std::to_string(declaredObjects) + " but holds " +
         std::to_string(objects - 1));
  }
}
} // namespace

itk::CenterlineTree
ReadTubeTree(const std::string & path, CoordinateSpace space, CenterlineReadReport & report)
{
  using ReaderType = itk::SpatialObjectReader<3>;
  report.Format = "TubeTK .tre";
  auto                reader = ReaderType::New();
  itk::CenterlineTree tree;
  std::string         metaText;
  {
    CheckTubeFile(path);
    const ScopedConsoleCapture metaMessages;
    try
    {
      reader->SetFileName(path);
      reader->Update();
      tree = itk::CenterlineTree::FromSpatialObject(reader->GetGroup());
    }
    catch (const InputError &)
    {
      throw;
    }
    catch (const itk::ExceptionObject & exception)
    {
      const std::string detail = metaMessages.FirstLine();
      throw InputError("centerline file " + path + ": not a readable TubeTK/MetaIO .tre file: " +
                       CondenseITKMessage(exception) + (detail.empty() ? std::string() : " (" + detail + ")"));
    }
    catch (const std::exception & exception)
    {
      // MetaIO's own parsing throws standard exceptions on some malformed lines (fuzzing: MET_ReadSubType).
      throw InputError("centerline file " + path + ": not a readable TubeTK/MetaIO .tre file: MetaIO failed (" +
                       std::string(exception.what()).substr(0, 200) + ")");
    }
    metaText = metaMessages.FirstLine();
  }
  if (tree.GetNumberOfBranches() == 0)
  {
    throw InputError("centerline file " + path + ": holds no tube with points (ObjectType = Tube)" +
                     (metaText.empty() ? std::string() : "; MetaIO says: " + metaText));
  }
  const CoordinateSpace used = space == CoordinateSpace::Auto ? CoordinateSpace::LPS : space;
  report.FileSpace = used;
  report.SpaceSource = space == CoordinateSpace::Auto ? "TubeTK files are LPS" : "override";
  report.RadiusArray = tree.HasRadii() ? "tube point radius" : "";
  report.InputPolylines = tree.GetNumberOfBranches();
  return used == CoordinateSpace::RAS ? FlipRASLPS(tree) : tree;
}

void
WriteTubeTree(const itk::CenterlineTree & tree,
              const std::string &         finalPath,
              const std::string &         temporaryPath,
              CoordinateSpace             space)
{
  using WriterType = itk::SpatialObjectWriter<3>;
  const itk::CenterlineTree  written = space == CoordinateSpace::RAS ? FlipRASLPS(tree) : tree;
  auto                       writer = WriterType::New();
  const ScopedConsoleCapture metaMessages;
  try
  {
    writer->SetInput(written.ToSpatialObject());
    writer->SetFileName(temporaryPath);
    writer->SetBinaryPoints(true); // float32 positions, not 6-digit text
    writer->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("centerline output " + finalPath +
                     ": could not be written: " + CondenseITKMessage(exception, temporaryPath, finalPath));
  }
}
} // namespace vr::detail
