// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCTAPhantom_h
#define itkCTAPhantom_h

#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "itkImageSource.h"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace itk
{
/** The built-in synthetic CT angiographies.
 * \ingroup VesselReformation */
enum class CTAPhantomKind
{
  /** RunoffPhantomImageSource: aorta to ankles, the paper's Figure 2. */
  Runoff,
  /** ThoraxPhantomImageSource: the aortic arch and its branches, the paper's thoracic figure. */
  Thorax
};

/** Prints the phantom's name, "runoff" or "thorax". */
std::ostream &
operator<<(std::ostream & os, CTAPhantomKind kind);

/** \class CTAPhantom
 * \brief One built-in phantom, ready for a demo, a viewer or a test: the volume source (not yet updated), its exact
 * centerline tree, the view it was designed for and the names of its arteries.
 *
 * \code
 * const auto phantom = itk::MakeCTAPhantom(itk::ParseCTAPhantomKind("thorax"), 1.5);
 * phantom.Source->Update();                      // the CT volume, HU, LPS mm
 * view.AngleInDegrees = phantom.DesignAngleInDegrees;
 * \endcode
 * \sa RunoffPhantomImageSource, ThoraxPhantomImageSource
 * \ingroup VesselReformation
 */
struct CTAPhantom
{
  CTAPhantomKind Kind{ CTAPhantomKind::Runoff };
  /** "runoff" or "thorax". */
  std::string Name;
  /** A phrase for messages and captions, e.g. "synthetic thoracic CTA (aortic arch)". */
  std::string                           Description;
  ImageSource<Image<float, 3>>::Pointer Source;
  CenterlineTree                        Tree;
  /** The view angle about the patient's superior axis, degrees, for which the phantom was designed. */
  double DesignAngleInDegrees{ 0.0 };
  /** The anatomical name of a branch id ("unknown" for ids not in the tree). */
  std::function<std::string(int)> BranchName;
};

/** The phantom \a kind with isotropic voxels of \a spacing mm. */
CTAPhantom
MakeCTAPhantom(CTAPhantomKind kind, double spacing = 1.5);

/** The names MakeCTAPhantom() knows, in CTAPhantomKind order: "runoff", "thorax". */
std::vector<std::string>
GetCTAPhantomNames();

/** The kind called \a name (any case). Throws std::invalid_argument naming the accepted names otherwise. */
CTAPhantomKind
ParseCTAPhantomKind(const std::string & name);
} // namespace itk

#endif
