// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrITKMessages.h"
#include "vrInputError.h"

#include "itkSpatialObjectReader.h"
#include "itkSpatialObjectWriter.h"

#include <iostream>
#include <sstream>

namespace vr::detail
{
namespace
{
/** MetaIO reports trouble on std::cout and std::cerr besides throwing: keep it for the message instead of
 * printing it. */
class MetaIOMessageCapture
{
public:
  MetaIOMessageCapture()
    : m_PreviousError(std::cerr.rdbuf(m_Text.rdbuf()))
    , m_PreviousOutput(std::cout.rdbuf(m_Text.rdbuf()))
  {
  }
  ~MetaIOMessageCapture()
  {
    std::cerr.rdbuf(m_PreviousError);
    std::cout.rdbuf(m_PreviousOutput);
  }
  MetaIOMessageCapture(const MetaIOMessageCapture &) = delete;
  MetaIOMessageCapture &
  operator=(const MetaIOMessageCapture &) = delete;

  /** The first line MetaIO printed (it repeats itself line by line). */
  std::string
  Text() const
  {
    std::string text = m_Text.str();
    text = text.substr(0, text.find('\n'));
    while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
    {
      text.pop_back();
    }
    return text;
  }

private:
  std::ostringstream m_Text;
  std::streambuf *   m_PreviousError;
  std::streambuf *   m_PreviousOutput;
};
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
    MetaIOMessageCapture metaMessages;
    try
    {
      reader->SetFileName(path);
      reader->Update();
      tree = itk::CenterlineTree::FromSpatialObject(reader->GetGroup());
    }
    catch (const itk::ExceptionObject & exception)
    {
      const std::string detail = metaMessages.Text();
      throw InputError("centerline file " + path + ": not a readable TubeTK/MetaIO .tre file: " +
                       CondenseITKMessage(exception) + (detail.empty() ? std::string() : " (" + detail + ")"));
    }
    metaText = metaMessages.Text();
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
  const itk::CenterlineTree written = space == CoordinateSpace::RAS ? FlipRASLPS(tree) : tree;
  auto                      writer = WriterType::New();
  MetaIOMessageCapture      metaMessages;
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
