# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# The module description: the one source of truth for the four command-line modules' XML (Vessel Reformation,
# Bilateral Depth Relax, Extract Centerlines, Vessel Path Reformation: Module/<name>/<name>.xml.in, beside each
# module's code) and for vrModuleDescription.h, which platforms and widgets include.
# Plain text only: the values are pasted into XML, so no <, > or &.

set(VR_MODULE_TITLE "Vessel Reformation")
set(VR_MODULE_CATEGORY "Vascular")
set(VR_MODULE_VERSION "${PROJECT_VERSION}")
# No public documentation page exists: the README and docs/ travel with the source.
set(VR_MODULE_DOCUMENTATION_URL "")
# The licence of the source distribution (its LICENSE file), as ITK's and 3D Slicer's.
set(VR_MODULE_LICENSE "Apache License 2.0")
set(VR_MODULE_CONTRIBUTORS "The VesselReformation developers")
set(VR_MODULE_HELP [=[Multipath curved planar reformation (mpCPR) of a whole vessel tree in one rotatable image, with the bilateral depth filter that removes the seams and scan-line flicker of the depth map while keeping meaningful depth jumps and cutting every vessel exactly along its centerline. Inputs: a CT or MR angiography volume and its centerlines (VMTK .vtp/.vtk, 3D Slicer .mrk.json curves, TubeTK .tre or CSV). Outputs: the filtered and unfiltered CPR images, the depth map before and after relaxation, the fixed mask, the owner labels, the cut surface as a model, and a windowed PNG.]=])
set(VR_MODULE_ACKNOWLEDGEMENTS [=[Implements the method of Jan Kretschmer, Bernhard Preim and Marc Stamminger, "Bilateral Depth Filtering for Enhanced Vessel Reformation", Eurographics Conference on Visualization (EuroVis) 2014, short paper. Built on ITK and VTK; shaped after the 3D Slicer execution model.]=])

# The relax-only module shares everything but its title and help.
set(VR_RELAX_MODULE_TITLE "Bilateral Depth Relax")
set(VR_RELAX_MODULE_HELP [=[The bilateral depth filter of the Vessel Reformation module on its own, for pipelines of your own: relaxes a depth map (for example the outputDepth of Vessel Reformation) with the iterated 4-neighbour bilateral filter of Kretschmer et al. (Eq. 1 and 2), keeping the pixels of an optional fixed mask unchanged. The output keeps the input's metadata, including the CPR view.]=])

# The centerline extraction module: a segmentation in, centerlines out, for the reformation or any other tool.
set(VR_EXTRACT_MODULE_TITLE "Extract Centerlines")
set(VR_EXTRACT_MODULE_HELP [=[Extracts the centerline tree of the vessels in a segmentation, with the lumen radius at every point, and writes it in every format the Vessel Reformation module reads. The segmentation is a label map or binary mask (from TotalSegmentator, an nnU-Net model, thresholding or 3D Slicer's Segment Editor), a VMTK level set (inside where negative) or a probability map; labels can be chosen, and several masks combined. Each connected component gives a tree rooted at its widest end or at a given point, split at bifurcations, with spurious short branches pruned; any orientation and voxel spacing.]=])

# The single-vessel reading: one path of the tree straightened, its cross-sections and its lumen measured.
set(VR_PATH_MODULE_TITLE "Vessel Path Reformation")
set(VR_PATH_MODULE_HELP [=[Reads one vessel of the tree: a path from the tree's root to the far end of a chosen branch (by default the longest root-to-leaf path), shown as a straightened or stretched curved planar reformation on a rotation-minimising frame that does not twist (roll about the path in degrees), the cross-sections perpendicular to it as a stack, and the lumen measured along it: area, circle-equivalent, minimum and maximum diameter of each cross-section from a segmentation (or the centerline radius without one), the reference diameter, the minimal lumen diameter and area with their position, the percent diameter and area stenosis and its CAD-RADS class. Every pixel maps back to its patient position (a point image), and pixels where neighbouring planes fold over each other at tight bends are marked and counted.]=])
