#ifndef vrImageIO_h
#define vrImageIO_h

#include "itkImage.h"

#include <string>

class vtkPolyData;

namespace vr
{
using DepthImageType = itk::Image<float, 2>;
using MaskImageType = itk::Image<unsigned char, 2>;
using LabelImageType = itk::Image<uint32_t, 2>;

/** Writes a 2D output (NRRD or any ITK format by extension) atomically, with its metadata dictionary (the CPR
 * view, as CPR_* key/value pairs in NRRD). Throws vr::InputError naming the path. */
void
WriteImage2D(const DepthImageType * image, const std::string & path);
void
WriteImage2D(const MaskImageType * image, const std::string & path);
void
WriteImage2D(const LabelImageType * image, const std::string & path);

/** Reads a 2D depth image (and its metadata) or a mask; throws vr::InputError naming the file. */
DepthImageType::Pointer
ReadDepthImage(const std::string & path);
MaskImageType::Pointer
ReadMaskImage(const std::string & path);

/** Writes an 8-bit PNG of \a image through window/level (intensities level -+ window/2 map to 0..255). */
void
WriteWindowedPNG(const DepthImageType * image, double window, double level, const std::string & path);

/** Writes a surface (.vtp XML or legacy .vtk) atomically. */
void
WriteSurface(vtkPolyData * surface, const std::string & path);
} // namespace vr

#endif
