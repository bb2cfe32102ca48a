// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineNode_h
#define vrCenterlineNode_h

#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace vr
{
/** \class CenterlineNode
 * \brief The centerlines of a vessel tree as a platform hands them over: a vtkPolyData whose polylines are the
 * branches, points in RAS millimetres, with a lumen radius point array (mm), as 3D Slicer's models and curves
 * hold them.
 *
 * The polylines may be VMTK's overlapping source-to-target paths: the conversion to a tree
 * (vr::CenterlineTreeFromPolyData) merges them so that each vessel section is one branch. Radii come from the point
 * array "MaximumInscribedSphereRadius" (VMTK) or "Radius" (3D Slicer); without one the lumen is unknown. A cell
 * array "BranchIds" names the branches when each polyline is one.
 *
 * \sa VolumeNode, VesselReformationLogic, vrNodeConversion.h
 * \ingroup VesselReformation
 */
class CenterlineNode : public vtkObject
{
public:
  static CenterlineNode *
  New();
  vtkTypeMacro(CenterlineNode, vtkObject);
  void
  PrintSelf(ostream & os, vtkIndent indent) override;

  /** \param polyData the polylines (RAS mm); the node keeps a reference. */
  void
  SetPolyData(vtkPolyData * polyData);
  /** \return the polylines, or null. */
  vtkPolyData *
  GetPolyData() const
  {
    return m_PolyData;
  }

  /** \param name a name for messages ("aorta-centerline.vtp"). */
  void
  SetName(const std::string & name);
  /** \return the name. */
  const std::string &
  GetName() const
  {
    return m_Name;
  }

  /** \return the latest modification time of the node and its polydata. */
  vtkMTimeType
  GetMTime() override;

protected:
  CenterlineNode();
  ~CenterlineNode() override;

private:
  CenterlineNode(const CenterlineNode &) = delete;
  void
  operator=(const CenterlineNode &) = delete;

  vtkSmartPointer<vtkPolyData> m_PolyData;
  std::string                  m_Name;
};
} // namespace vr

#endif
