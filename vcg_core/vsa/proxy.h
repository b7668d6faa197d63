// Variational Shape Approximation for vcglib — proxies and partitions, the data passed from
// the partitioning stage to the meshing stage.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PROXY_H
#define VSA_PROXY_H

#include <vcg/space/point3.h>

#include <cstring>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// A planar proxy: a point on the plane and its unit normal.
struct Proxy
{
    Point3d point;
    Point3d normal;
};

/// Whether two lists of proxies are the same, bit for bit (a fixed point of Lloyd iterations).
inline bool SameProxies(const std::vector<Proxy> &a, const std::vector<Proxy> &b)
{
    static_assert(sizeof(Proxy) == 6 * sizeof(double), "a Proxy is six doubles, without padding");
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Proxy)) == 0);
}

/// A partition of an IndexedMesh's faces into regions, each approximated by one proxy.
struct Partition
{
    std::vector<int> faceRegion;   ///< per face: region index in [0, proxies.size())
    std::vector<Proxy> proxies;    ///< per region
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PROXY_H
