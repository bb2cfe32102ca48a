#include "vrCenterlineFormats.h"
#include "vrInputError.h"

#include "itkSpatialObjectReader.h"
#include "itkSpatialObjectWriter.h"

#include <iostream>
#include <sstream>

namespace vr::detail
{
namespace
{
/** MetaIO reports trouble on std::cerr besides throwing: keep it for the message instead of printing it. */
class CerrCapture
{
public:
  CerrCapture()
    : m_Previous(std::cerr.rdbuf(m_Text.rdbuf()))
  {}
  ~CerrCapture() { std::cerr.rdbuf(m_Previous); }
  CerrCapture(const CerrCapture &) = delete;
  CerrCapture &
  operator=(const CerrCapture &) = delete;

  std::string
  Text() const
  {
    std::string text = m_Text.str();
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    return text;
  }

private:
  std::ostringstream m_Text;
  std::streambuf *   m_Previous;
};
} // namespace

itk::CenterlineTree
ReadTubeTree(const std::string & path, CoordinateSpace space, CenterlineReadReport & report)
{
  using ReaderType = itk::SpatialObjectReader<3>;
  report.Format = "TubeTK .tre";
  auto                reader = ReaderType::New();
  itk::CenterlineTree tree;
  {
    CerrCapture metaMessages;
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
                       exception.GetDescription() + (detail.empty() ? std::string() : " (" + detail + ")"));
    }
  }
  if (tree.GetNumberOfBranches() == 0)
  {
    throw InputError("centerline file " + path + ": holds no tube with points (ObjectType = Tube)");
  }
  const CoordinateSpace used = space == CoordinateSpace::Auto ? CoordinateSpace::LPS : space;
  report.FileSpace = used;
  report.SpaceSource = space == CoordinateSpace::Auto ? "TubeTK files are LPS" : "override";
  report.RadiusArray = tree.HasRadii() ? "tube point radius" : "";
  report.InputPolylines = tree.GetNumberOfBranches();
  return used == CoordinateSpace::RAS ? FlipRASLPS(tree) : tree;
}

void
WriteTubeTree(const itk::CenterlineTree & tree, const std::string & finalPath, const std::string & temporaryPath,
              CoordinateSpace space)
{
  using WriterType = itk::SpatialObjectWriter<3>;
  const itk::CenterlineTree written = space == CoordinateSpace::RAS ? FlipRASLPS(tree) : tree;
  auto                      writer = WriterType::New();
  CerrCapture               metaMessages;
  try
  {
    writer->SetInput(written.ToSpatialObject());
    writer->SetFileName(temporaryPath);
    writer->SetBinaryPoints(true); // float32 positions, not 6-digit text
    writer->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("centerline output " + finalPath + ": could not be written: " + exception.GetDescription());
  }
}
} // namespace vr::detail
