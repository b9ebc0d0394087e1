// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/terminal.hpp"

#include <windows.h>

#include <algorithm>

#include "platform/os_error_win.hpp"

namespace tactus::platform {
namespace {

HANDLE handle_of(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }

bool is_pipe_name(const std::string& path) { return path.rfind("\\\\.\\pipe\\", 0) == 0; }

// "COM10" and above open only as \\.\COM10; the prefix works for every port.
std::string device_name(const std::string& path) {
    if (path.rfind("\\\\", 0) == 0) return path;
    return "\\\\.\\" + path;
}

std::string open_error(DWORD code) {
    switch (code) {
        case ERROR_FILE_NOT_FOUND:
        case ERROR_PATH_NOT_FOUND: return "no such device";
        case ERROR_ACCESS_DENIED:
        case ERROR_SHARING_VIOLATION:
        case ERROR_PIPE_BUSY: return "busy (in use by another program)";
        default: return os_error_from_code(code).what;
    }
}

OsResult<void> configure(HANDLE h, const LineSettings& line) {
    DCB dcb{};
    dcb.DCBlength = sizeof dcb;
    if (!GetCommState(h, &dcb)) return os_fail("not a serial port: " + last_error().what);
    switch (line.baud) {
        case 1200: case 2400: case 4800: case 9600: case 19200: case 38400: case 57600: case 115200: case 230400:
            dcb.BaudRate = static_cast<DWORD>(line.baud);
            break;
        default: return os_fail("unsupported baud rate " + std::to_string(line.baud), OsErrorKind::unsupported);
    }
    dcb.fBinary = TRUE;
    dcb.ByteSize = 8;
    dcb.fParity = line.parity != 'n';
    dcb.Parity = line.parity == 'o' ? ODDPARITY : line.parity == 'e' ? EVENPARITY : NOPARITY;
    dcb.StopBits = line.stop_bits == 2 ? TWOSTOPBITS : ONESTOPBIT;
    dcb.fOutxCtsFlow = line.flow == LineSettings::Flow::rtscts;
    dcb.fRtsControl = line.flow == LineSettings::Flow::rtscts ? RTS_CONTROL_HANDSHAKE : RTS_CONTROL_ENABLE;
    dcb.fOutX = dcb.fInX = line.flow == LineSettings::Flow::xonxoff;
    dcb.fDtrControl = DTR_CONTROL_ENABLE;
    dcb.fOutxDsrFlow = FALSE;
    dcb.fDsrSensitivity = FALSE;
    dcb.fNull = FALSE;
    dcb.fAbortOnError = FALSE;
    if (!SetCommState(h, &dcb)) return os_fail("cannot set the port's mode: " + last_error().what);
    // Reads return what is there at once; read() below does the waiting.
    COMMTIMEOUTS t{};
    t.ReadIntervalTimeout = MAXDWORD;
    t.WriteTotalTimeoutConstant = 1000;
    if (!SetCommTimeouts(h, &t)) return os_fail("cannot set the port's timeouts: " + last_error().what);
    return {};
}

std::size_t waiting(HANDLE h, bool pipe) {
    if (pipe) {
        DWORD avail = 0;
        return PeekNamedPipe(h, nullptr, 0, nullptr, &avail, nullptr) ? avail : 0;
    }
    COMSTAT st{};
    DWORD errors = 0;
    return ClearCommError(h, &errors, &st) ? st.cbInQue : 0;
}

}  // namespace

OsResult<Terminal> Terminal::open(const std::string& path, const LineSettings& line) {
    // No sharing: the port is this program's alone while it is open.
    const std::wstring name = widen(device_name(path));
    HANDLE h = CreateFileW(name.c_str(), GENERIC_READ | GENERIC_WRITE, 0, nullptr, OPEN_EXISTING, 0, nullptr);
    DWORD code = h == INVALID_HANDLE_VALUE ? GetLastError() : ERROR_SUCCESS;
    // The simulator's pipe takes its next client once it has seen the last
    // one leave; still taken after a second, it is busy.
    if (code == ERROR_PIPE_BUSY && is_pipe_name(path) && WaitNamedPipeW(name.c_str(), 1000)) {
        h = CreateFileW(name.c_str(), GENERIC_READ | GENERIC_WRITE, 0, nullptr, OPEN_EXISTING, 0, nullptr);
        code = h == INVALID_HANDLE_VALUE ? GetLastError() : ERROR_SUCCESS;
    }
    if (h == INVALID_HANDLE_VALUE) return os_fail(open_error(code), os_error_from_code(code).kind);
    Terminal t(reinterpret_cast<std::intptr_t>(h));
    if (!is_pipe_name(path)) {
        if (auto r = configure(h, line); !r) return std::unexpected(r.error());
    }
    return t;
}

Terminal& Terminal::operator=(Terminal&& o) noexcept {
    if (this != &o) {
        if (handle_ != -1) CloseHandle(handle_of(handle_));
        handle_ = o.release();
    }
    return *this;
}

Terminal::~Terminal() {
    if (handle_ != -1) CloseHandle(handle_of(handle_));
}

OsResult<void> Terminal::write_all(std::span<const std::uint8_t> bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        DWORD wrote = 0;
        if (!WriteFile(handle_of(handle_), bytes.data() + done, static_cast<DWORD>(bytes.size() - done), &wrote,
                       nullptr))
            return os_fail("device disconnected: " + last_error().what);
        if (wrote == 0) return os_fail("write timed out (line blocked)");
        done += wrote;
    }
    return {};
}

OsResult<std::size_t> Terminal::read(std::span<std::uint8_t> buffer, std::chrono::microseconds timeout) {
    const HANDLE h = handle_of(handle_);
    const bool pipe = GetFileType(h) == FILE_TYPE_PIPE;
    // Polled by the millisecond: a COM port's WaitCommEvent and a pipe's
    // readiness need overlapped I/O, which this handle was not opened for.
    const auto until = std::chrono::steady_clock::now() + timeout;
    while (waiting(h, pipe) == 0) {
        if (pipe) {
            DWORD avail = 0;
            if (!PeekNamedPipe(h, nullptr, 0, nullptr, &avail, nullptr)) return os_fail("device disconnected");
        }
        if (std::chrono::steady_clock::now() >= until) return std::size_t{0};
        Sleep(1);
    }
    const auto want = static_cast<DWORD>(std::min(buffer.size(), waiting(h, pipe)));
    DWORD got = 0;
    if (!ReadFile(h, buffer.data(), want, &got, nullptr)) return os_fail("device disconnected");
    return std::size_t{got};
}

}  // namespace tactus::platform
