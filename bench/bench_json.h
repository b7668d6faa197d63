// Shared by the benchmark drivers: one JSON object per line, a stopwatch and peak memory.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_BENCH_JSON_H
#define VSA_BENCH_JSON_H

#include <sys/resource.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <type_traits>

namespace vsa_bench {

/// Builds one JSON object whose keys keep the order they were added in, so every line of a
/// benchmark log reads the same way. Usage:
///   JsonLine line;
///   line.Add("tool", "cgal").Add("faces", 12946).Add("energy", 0.25).Add("closed", true);
///   line.Print();  // {"tool":"cgal","faces":12946,"energy":0.25,"closed":true}
class JsonLine
{
public:
    JsonLine &Add(const std::string &key, const std::string &value) { return AddRaw(key, Quoted(value)); }
    JsonLine &Add(const std::string &key, const char *value) { return AddRaw(key, Quoted(value)); }

    /// Booleans, integers of any width, and floating-point numbers. Doubles are written with
    /// the shortest digits that read back to the same value; NaN and infinity become null.
    template <class Number, class = std::enable_if_t<std::is_arithmetic_v<Number>>>
    JsonLine &Add(const std::string &key, Number value)
    {
        if constexpr (std::is_same_v<Number, bool>) {
            return AddRaw(key, value ? "true" : "false");
        } else if constexpr (std::is_floating_point_v<Number>) {
            if (!std::isfinite(value)) return AddRaw(key, "null");
            char digits[32];
            const auto end = std::to_chars(digits, digits + sizeof digits, double(value)).ptr;
            return AddRaw(key, std::string(digits, end));
        } else {
            return AddRaw(key, std::to_string(value));
        }
    }

    JsonLine &AddNull(const std::string &key) { return AddRaw(key, "null"); }

    std::string Str() const { return "{" + body_ + "}"; }

    /// Writes the object and a newline, flushed, so a crash later cannot lose the line.
    void Print(std::ostream &out = std::cout) const { out << Str() << std::endl; }

private:
    JsonLine &AddRaw(const std::string &key, const std::string &jsonValue)
    {
        if (!body_.empty()) body_ += ',';
        body_ += Quoted(key) + ':' + jsonValue;
        return *this;
    }

    static std::string Quoted(const std::string &text)
    {
        std::string quoted = "\"";
        for (const char c : text) {
            switch (c) {
                case '"': quoted += "\\\""; break;
                case '\\': quoted += "\\\\"; break;
                case '\n': quoted += "\\n"; break;
                case '\t': quoted += "\\t"; break;
                default:
                    if (static_cast<unsigned char>(c) < 0x20) {
                        char escaped[8];
                        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                        quoted += escaped;
                    } else {
                        quoted += c;
                    }
            }
        }
        return quoted + '"';
    }

    std::string body_;
};

/// Wall-clock time from construction or the last Restart(); steady, so clock changes don't
/// show up as timings.
class Stopwatch
{
public:
    void Restart() { start_ = Clock::now(); }
    double Seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
};

/// The largest resident set size the process has had so far, in MiB (Linux reports KiB).
inline double PeakRssMb()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;
}

/// The resident set size now, in MiB, from /proc/self/statm (Linux); 0 where that is missing.
inline double CurrentRssMb()
{
    long pages = 0, resident = 0;
    if (FILE *f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

}  // namespace vsa_bench

#endif  // VSA_BENCH_JSON_H
