// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/sim_endpoint.hpp"
#include "platform/posix_fd.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cstdlib>

namespace tactus::platform {

OsResult<SimEndpoint> SimEndpoint::open(bool nonblocking) {
    SimEndpoint s;
    const int master = cloexec_pt_master();
    if (master < 0) return os_fail("cannot open a pseudo-terminal: " + last_error().what);
    s.line_ = Channel(master);
    if (grantpt(master) != 0 || unlockpt(master) != 0) return os_fail("cannot unlock the pseudo-terminal");
    const char* name = ptsname(master);
    if (!name) return os_fail("pseudo-terminal has no name");
    s.path_ = name;
    const int slave = ::open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (slave < 0) return os_fail("cannot open " + s.path_);
    s.keep_ = Channel(slave);
    // Raw: every byte value passes, none is a line edit or a signal.
    termios t{};
    if (tcgetattr(slave, &t) != 0) return std::unexpected(last_error());
    cfmakeraw(&t);
    if (tcsetattr(slave, TCSANOW, &t) != 0) return std::unexpected(last_error());
    if (nonblocking) {
        const int flags = fcntl(master, F_GETFL);
        fcntl(master, F_SETFL, flags | O_NONBLOCK);
    }
    return s;
}

}  // namespace tactus::platform
