// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkThoraxPhantomImageSource_h
#define itkThoraxPhantomImageSource_h

#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "itkImageSource.h"

#include <string>

namespace itk
{

/** \class ThoraxPhantomImageSource
 * \brief A synthetic thoracic CT angiography (arterial phase), in Hounsfield units, with its exact centerline tree.
 *
 * The aorta rises from the left ventricle as the ascending aorta, anterior and to the right, turns over the left main
 * bronchus as the arch and descends left of the spine to the diaphragm. From the arch rise the brachiocephalic trunk
 * (dividing into the right subclavian and right common carotid arteries), the left common carotid and the left
 * subclavian artery. Around them: the heart (myocardium, a contrast-filled left ventricle, the less enhanced right
 * heart), the pulmonary trunk and arteries (enhanced, not in the tree), both lungs (-850 HU), the trachea and main
 * bronchi (air), mediastinal and subcutaneous fat, chest-wall and neck muscles with thin fat planes between them, the
 * thoracic spine (vertebral bodies and spinous processes), eleven pairs of ribs, the sternum and clavicles (cortical
 * bone around marrow), a few calcified plaques in the arch wall, air around the body, and reproducible noise.
 *
 * Patient frame LPS, millimetres; z = 0 is about the top of the aortic arch, the field of view runs from the upper
 * abdomen (z = -235) into the neck (z = +115). The supra-aortic branches run a few millimetres to 15 mm apart in
 * depth in an anterior view, so the scanline mpCPR depth map has the 2-10 mm scan-line seams of real thoracic CTA
 * at and above the arch, while the ascending and descending aorta lie about 55 mm apart in depth. The volume is drawn
 * from the same polylines GetCenterlineTree() returns, so the tree is exact.
 *
 * \sa RunoffPhantomImageSource, CPRDepthImageFilter
 * \ingroup VesselReformation
 */
class ThoraxPhantomImageSource : public ImageSource<Image<float, 3>>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(ThoraxPhantomImageSource);

  using Self = ThoraxPhantomImageSource;
  using Superclass = ImageSource<Image<float, 3>>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;
  using ImageType = Image<float, 3>;

  itkNewMacro(Self);
  itkTypeMacro(ThoraxPhantomImageSource, ImageSource);

  /** The view angle (degrees about superior) the phantom was designed for: 0, the anterior view of the arch. */
  static constexpr double DesignAngleInDegrees = 0.0;

  /** Isotropic voxel spacing, in mm. */
  itkSetMacro(Spacing, double);
  itkGetConstMacro(Spacing, double);
  /** Standard deviation of the image noise, in HU. */
  itkSetMacro(NoiseStandardDeviation, double);
  itkGetConstMacro(NoiseStandardDeviation, double);
  /** Seed of the noise. */
  itkSetMacro(Seed, unsigned int);
  itkGetConstMacro(Seed, unsigned int);

  /** The exact centerlines (LPS mm) with lumen radii (mm); ids label the arteries, each branch carries its name
   * (GetBranchName). */
  CenterlineTree
  GetCenterlineTree() const;
  /** The anatomical name of a branch id, e.g. "left subclavian artery"; "unknown" for other ids. */
  static std::string
  GetBranchName(int id);

protected:
  ThoraxPhantomImageSource();
  ~ThoraxPhantomImageSource() override = default;

  void
  VerifyPreconditions() ITKv5_CONST override;
  void
  GenerateOutputInformation() override;
  void
  DynamicThreadedGenerateData(const OutputImageRegionType & region) override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  double       m_Spacing{ 1.5 };
  double       m_NoiseStandardDeviation{ 15.0 };
  unsigned int m_Seed{ 2014 };
};

} // namespace itk

#endif
