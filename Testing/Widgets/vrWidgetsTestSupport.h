// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrWidgetsTestSupport_h
#define vrWidgetsTestSupport_h

#include "vrReformationInputs.h"
#include "vrReformationParameters.h"
#include "vrVesselReformationLogic.h"
#include "vrViewerWindow.h"

#include <QPointF>
#include <QString>

class QImage;
class QMessageBox;

#include <functional>
#include <memory>

/** What the widget tests share: a small phantom made once, windows showing it, event-loop waits, mouse events, and
 * the reference: an independent VesselReformationLogic run on the same nodes. */
namespace vr::test
{
/** The run-off phantom at 3 mm voxels (fast to make), made once per process. */
ReformationInputs
SmallPhantomInputs();

/** The view the tests reform at: 128 x 256 pixels, 200 iterations on the CPU, w = 1, a = 0.5, at \a angle. */
ReformationParameters
TestParameters(double angle);

/** Processes events until \a done() or \a seconds pass. \return done(). */
bool
WaitUntil(const std::function<bool()> & done, double seconds = 120.0);

/** Processes events until the controller is idle and the views have drawn what it delivered. \return false on a
 * timeout. */
bool
WaitUntilSettled(ViewerWindow & window, double seconds = 120.0);

/** A shown viewer window with the small phantom reformed at TestParameters(\a angle), overlays off. */
std::unique_ptr<ViewerWindow>
MakeWindowOnSmallPhantom(double angle);

/** The reference: a VesselReformationLogic of its own on \a inputs' nodes with \a parameters. */
ReformationOutputs
ReferenceOutputs(const ReformationInputs & inputs, const ReformationParameters & parameters);

/** Sends a mouse event to \a widget at \a position (logical pixels). */
void
SendMouse(QWidget * widget, int type, const QPointF & position, Qt::MouseButton button, Qt::MouseButtons buttons);

/** The float pixels of a one-slice node, row-major. */
std::vector<float>
NodePixels(VolumeNode * node);

/** Whole-run stage counts after minus before. */
struct Runs
{
  unsigned int Conversion, Depth, Relax, Resample, UnfilteredSamplings, RelaxedSamplings, Surface;
};
Runs
Difference(const ReformationStageCounts & after, const ReformationStageCounts & before);

/** The grey value VTK shows for \a value through window/level, read back from the CPR view's frame. */
int
FrameGrey(const QImage & frame, const QPointF & position);

/** Checks that the image data the CPR view's actor draws is \a expected, pixel for pixel. */
void
ExpectSameImage(CPRView & view, VolumeNode * expected);

/** Checks that the CPR view shows exactly \a expected (the logic's CPR): the image data its actor draws equals it
 * pixel for pixel, and the frame on screen shows those pixels through window/level. */
void
ExpectShows(ViewerWindow & window, VolumeNode * expected);

/** The error dialog the window opened, or null. */
QMessageBox *
ErrorDialog(ViewerWindow & window);
} // namespace vr::test

#endif
