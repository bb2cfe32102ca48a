# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# The module description: the one source of truth for both command-line modules' XML
# (Module/<name>/<name>.xml.in, beside each module's code) and for vrModuleDescription.h, which
# platforms and widgets include.
# Plain text only: the values are pasted into XML, so no <, > or &.

set(VR_MODULE_TITLE "Vessel Reformation")
set(VR_MODULE_CATEGORY "Vascular")
set(VR_MODULE_VERSION "${PROJECT_VERSION}")
# No public documentation page or licence file exists yet; fill these in when they do.
set(VR_MODULE_DOCUMENTATION_URL "")
set(VR_MODULE_LICENSE "See the licence of the VesselReformation source distribution.")
set(VR_MODULE_CONTRIBUTORS "The VesselReformation developers")
set(VR_MODULE_HELP [=[Multipath curved planar reformation (mpCPR) of a whole vessel tree in one rotatable image, with the bilateral depth filter that removes the seams and scan-line flicker of the depth map while keeping meaningful depth jumps and cutting every vessel exactly along its centerline. Inputs: a CT or MR angiography volume and its centerlines (VMTK .vtp/.vtk, 3D Slicer .mrk.json curves, TubeTK .tre or CSV). Outputs: the filtered and unfiltered CPR images, the depth map before and after relaxation, the fixed mask, the owner labels, the cut surface as a model, and a windowed PNG.]=])
set(VR_MODULE_ACKNOWLEDGEMENTS [=[Implements the method of Jan Kretschmer, Bernhard Preim and Marc Stamminger, "Bilateral Depth Filtering for Enhanced Vessel Reformation", Eurographics Conference on Visualization (EuroVis) 2014, short paper. Built on ITK and VTK; shaped after the 3D Slicer execution model.]=])

# The relax-only module shares everything but its title and help.
set(VR_RELAX_MODULE_TITLE "Bilateral Depth Relax")
set(VR_RELAX_MODULE_HELP [=[The bilateral depth filter of the Vessel Reformation module on its own, for pipelines of your own: relaxes a depth map (for example the outputDepth of Vessel Reformation) with the iterated 4-neighbour bilateral filter of Kretschmer et al. (Eq. 1 and 2), keeping the pixels of an optional fixed mask unchanged. The output keeps the input's metadata, including the CPR view.]=])

# The centerline extraction module: a segmentation in, centerlines out, for the reformation or any other tool.
set(VR_EXTRACT_MODULE_TITLE "Extract Centerlines")
set(VR_EXTRACT_MODULE_HELP [=[Extracts the centerline tree of the vessels in a segmentation, with the lumen radius at every point, and writes it in every format the Vessel Reformation module reads. The segmentation is a label map or binary mask (from TotalSegmentator, an nnU-Net model, thresholding or 3D Slicer's Segment Editor), a VMTK level set (inside where negative) or a probability map; labels can be chosen, and several masks combined. Each connected component gives a tree rooted at its widest end or at a given point, split at bifurcations, with spurious short branches pruned; any orientation and voxel spacing.]=])
