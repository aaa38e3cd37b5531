// An X display for the --pictures of every command, started when there is none.
//
// Debian's VTK 9.1 is built without EGL and OSMesa: its only render window is
// X's, which aborts the process when no display can be opened. On a machine
// without a display the command therefore starts a virtual framebuffer
// (Xvfb, Debian package xvfb) of its own before computing, as pyvista's
// start_xvfb does, and stops it when the process ends.
#pragma once

#include <string>

namespace surfacemap
{

/// Makes sure pictures can be rendered; empty when they can, otherwise why
/// not, as a sentence for the user. Uses the display DISPLAY names when it
/// opens; otherwise (DISPLAY unset, or naming a display that does not open)
/// starts Xvfb on a free display number it picks itself, waits until it
/// accepts connections and points DISPLAY at it. That server is stopped at
/// exit and, through the parent-death signal, also when the process is
/// killed. One X connection stays open until the process ends, which keeps
/// the server from resetting between pictures (every picture window closes
/// its own). Logs the virtual display's name at INFO (-v). Idempotent.
std::string prepareDisplay();

} // namespace surfacemap
