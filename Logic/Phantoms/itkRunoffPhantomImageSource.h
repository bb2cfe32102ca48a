// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkRunoffPhantomImageSource_h
#define itkRunoffPhantomImageSource_h

#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "itkImageSource.h"

namespace itk
{

/** \class RunoffPhantomImageSource
 * \brief A synthetic CT angiography of a leg run-off, in Hounsfield units, with its exact centerline tree.
 *
 * The distal aorta divides into the common iliac arteries; each gives an internal iliac (ending part-way) and
 * continues as external iliac, common femoral, superficial femoral and popliteal artery, with a deep femoral
 * artery (ending part-way) at the groin and the anterior tibial, posterior tibial and peroneal arteries below
 * the knee. Contrast-filled lumen 300-400 HU, a few calcified plaques ~1000 HU in the vessel walls, vertebral
 * bodies, femoral heads, femur, tibia and fibula (cortical bone ~1200 HU around marrow), muscle and
 * subcutaneous fat inside the body outline, air (-1000 HU) around it, and reproducible noise.
 *
 * Patient frame LPS, millimetres; z = 0 is the top of the field of view (infrarenal aorta), the feet are at
 * z = -1000 Scale. Neighbouring vessels of a leg run a few millimetres apart in depth, branches end part-way
 * (the scanline depth map's horizontal seams), and the two legs lie far apart in depth for oblique views.
 * The volume is drawn from the same polylines GetCenterlineTree() returns, so the tree is exact.
 *
 * \sa CPRDepthImageFilter
 * \ingroup VesselReformation
 */
class RunoffPhantomImageSource : public ImageSource<Image<float, 3>>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(RunoffPhantomImageSource);

  using Self = RunoffPhantomImageSource;
  using Superclass = ImageSource<Image<float, 3>>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;
  using ImageType = Image<float, 3>;
  using PointType = Point<double, 3>;

  itkNewMacro(Self);
  itkTypeMacro(RunoffPhantomImageSource, ImageSource);

  /** The view angle (degrees about superior) the phantom was designed for: there the vessels of each leg lie within a
   * few mm of each other in depth, so the scanline depth map has small seams inside each leg and a large jump between
   * the legs. */
  static constexpr double DesignAngleInDegrees = 30.0;

  /** Isotropic voxel spacing, in mm. */
  itkSetMacro(Spacing, double);
  itkGetConstMacro(Spacing, double);
  /** Size of the patient relative to an adult (1 = about 1 m from aorta to feet). */
  itkSetMacro(Scale, double);
  itkGetConstMacro(Scale, double);
  /** Standard deviation of the image noise, in HU. */
  itkSetMacro(NoiseStandardDeviation, double);
  itkGetConstMacro(NoiseStandardDeviation, double);
  /** Seed of the noise. */
  itkSetMacro(Seed, unsigned int);
  itkGetConstMacro(Seed, unsigned int);

  /** The exact centerlines (LPS mm) with lumen radii (mm); ids label the vessels, each branch carries its name
   * (GetBranchName). */
  CenterlineTree
  GetCenterlineTree() const;
  /** The anatomical name of a branch id, e.g. "left superficial femoral/popliteal". */
  static std::string
  GetBranchName(int id);

protected:
  RunoffPhantomImageSource();
  ~RunoffPhantomImageSource() override = default;

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
  double       m_Scale{ 1.0 };
  double       m_NoiseStandardDeviation{ 12.0 };
  unsigned int m_Seed{ 2014 };
};

} // namespace itk

#endif
