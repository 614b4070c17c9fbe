// libFuzzer target for everything in anim/mocap that reads untrusted bytes:
// BVH, ASF, AMC (against a small valid ASF), the graph and map blobs. The
// first byte picks the parser. Must never crash, hang or read out of bounds
// (ASan/UBSan); refusing is fine.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "anim/mocap/asf_amc_parser.hpp"
#include "anim/mocap/bvh_parser.hpp"
#include "anim/mocap/capability_map.hpp"
#include "anim/mocap/mocap_blob.hpp"

namespace {
const char* kAsf =
    ":units\nlength 0.45\nangle deg\n:root\norder TX TY TZ RX RY RZ\naxis XYZ\n:bonedata\nbegin\nname lfemur\n"
    "direction 0 -1 0\nlength 7\naxis 0 0 20 XYZ\ndof rx ry rz\nend\nbegin\nname ltibia\ndirection 0 -1 0\nlength 7\n"
    "axis 0 0 20 XYZ\ndof rx\nend\n:hierarchy\nbegin\nroot lfemur\nlfemur ltibia\nend\n";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  using namespace mc::anim::mocap;
  switch (data[0] % 5) {
    case 0: {
      BvhOptions o;
      o.max_frames = 2000;
      (void)parse_bvh(text, o);
      break;
    }
    case 1: (void)parse_asf(text); break;
    case 2: {
      static const AsfResult asf = parse_asf(kAsf);
      AmcOptions o;
      o.max_frames = 2000;
      (void)parse_amc(text, asf.skeleton, o);
      break;
    }
    case 3: {
      MotionGraph g;
      std::string error;
      (void)deserialize_graph(text, g, error);
      break;
    }
    default: {
      CapabilityMap m;
      std::string error;
      (void)deserialize_map(text, m, error);
      break;
    }
  }
  return 0;
}
