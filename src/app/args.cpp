#include "app/args.h"
#include "scene/user_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include "dsr_error.h"

namespace dsr {

void fail_command(const std::string& command, const std::string& what) { throw Error("dsr " + command + ": " + what); }

void Args::fail(const std::string& what) const { fail_command(cmd_, what); }

std::string Args::value(const std::string& flag) {
    if (done()) fail(flag + ": expected a value, got nothing");
    // An empty value never means "off": `--stats ''` from an unset shell variable is a mistake.
    if (peek().empty()) fail(flag + ": expected a value, got ''");
    return next();
}

static std::string format_number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
}

static bool parse_int(const std::string& s, long& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtol(s.c_str(), &end, 10);
    return errno == 0 && *end == '\0';
}

int Args::int_value(const std::string& flag, int lo, int hi) {
    std::string v = value(flag);
    long n;
    if (!parse_int(v, n) || n < lo || n > hi)
        fail(flag + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + quote(v));
    return int(n);
}

float Args::float_value(const std::string& flag, float lo, float hi) {
    std::string v = value(flag);
    char* end = nullptr;
    errno = 0;
    double d = v.empty() ? 0 : std::strtod(v.c_str(), &end);
    if (v.empty() || errno != 0 || *end != '\0' || !(d >= lo && d <= hi))
        fail(flag + ": expected a number in [" + format_number(lo) + ", " + format_number(hi) + "], got " + quote(v));
    return float(d);
}

void Args::size_value(const std::string& flag, int& w, int& h) {
    std::string v = value(flag);
    size_t x = v.find('x');
    long a, b;
    if (x == std::string::npos || !parse_int(v.substr(0, x), a) || !parse_int(v.substr(x + 1), b) || a < 1 ||
        b < 1 || a > 8192 || b > 8192)
        fail(flag + ": expected WIDTHxHEIGHT with each in [1, 8192], got " + quote(v));
    w = int(a);
    h = int(b);
}

bool Args::on_off(const std::string& flag) { return choice(flag, {"on", "off"}) == "on"; }

std::string Args::choice(const std::string& flag, const std::vector<std::string>& allowed) {
    std::string v = value(flag);
    std::string list;
    for (auto& a : allowed) {
        if (v == a) return v;
        list += (list.empty() ? "" : "|") + a;
    }
    fail(flag + ": expected " + list + ", got " + quote(v));
}

}  // namespace dsr
