// The text trace formats against the bounded-work rule (docs/RELIABILITY.md, "Work bounded by the
// input"): CSV and Dinero din are read line by line, so their loops consume input; what a line
// can still declare is sizes, the CSV's metadata (frame size, texture level sizes and counts) and
// din's access size. Generated: each hostile value in each place, replayed through a texture
// cache and a depth cache, must end in a moment with exit 0 (the sizes only address the caches)
// or exit 1 with a message naming the file, never run on or allocate by the declared size.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/run_rastrace.h"
#include "tests/support/temp_dir.h"

namespace rastrace {
namespace {

using testing::run_rastrace;
using testing::TempDir;

const char* kCsvBody =
    "event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,address,label,mask\n"
    "begin_draw,0,0,,,,,,,,,,,,,\n"
    "texel,,,,,,0,0,7,7,5,12,1,,,\n"
    "texel,,,,,,0,1,3,3,5,12,1,,,\n"
    "depth_read,,,,,,,,,,4,12,1,,,2\n"
    "depth_write,,,,,,,,,,4,12,1,,,2\n"
    "end_draw,,,,,,,,,,,,,,,\n";

std::string csv_with(const std::string& resolution, const std::string& textures) {
  return "# rastrace metadata: {\"filter\":\"trilinear\",\"ordering\":\"original\",\"resolution\":" + resolution +
         ",\"scene\":\"x\",\"textures\":" + textures + ",\"tool\":\"rastrace\",\"tool_version\":\"0.1.0\"}\n" + kCsvBody;
}

std::string repeated(const std::string& item, std::size_t n) {
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) out += (i ? "," : "") + item;
  return out + "]";
}

struct Case {
  std::string name, file_name, bytes;
};

std::vector<Case> cases() {
  const std::vector<std::string> sizes = {"65537", "2147483648", "4294967295", "18446744073709551615",
                                          "99999999999999999999", "-1", "1e300"};
  const std::string levels = "[[512,512],[256,256]]";
  std::vector<Case> out;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::string s = sizes[i], id = std::to_string(i);
    out.push_back({"csv_width_" + id, "w.csv", csv_with("[" + s + ",32]", "[" + levels + "]")});
    out.push_back({"csv_frame_" + id, "f.csv", csv_with("[" + s + "," + s + "]", "[" + levels + "]")});
    out.push_back({"csv_level_" + id, "l.csv", csv_with("[32,32]", "[[[" + s + "," + s + "],[256,256]]]")});
    out.push_back({"csv_all_levels_" + id, "a.csv", csv_with("[32,32]", "[" + repeated("[" + s + "," + s + "]", 64) + "]")});
    out.push_back({"din_address_" + id, "a.din", "0 " + s + "\n1 10\n"});
    out.push_back({"din_size_" + id, "s.din", "0 1000 " + s + "\n2 20 4\n"});
    out.push_back({"din_label_" + id, "l.din", s + " 1000\n"});
  }
  // Counts written out: as many levels and textures as a few hundred kilobytes of metadata hold.
  out.push_back({"csv_many_levels", "m.csv", csv_with("[32,32]", "[" + repeated("[1,1]", 50000) + "]")});
  out.push_back({"csv_many_textures", "t.csv", csv_with("[32,32]", repeated("[[1,1]]", 50000))});
  return out;
}

TEST(TextTraceCounts, EveryDeclaredSizeEndsInAResultOrAnErrorNamingTheFile) {
  const TempDir dir;
  const auto all = cases();
  EXPECT_EQ(all.size(), 51u);
  double slowest = 0;
  std::string slowest_name;
  for (const Case& c : all) {
    const std::string path = dir.write(c.file_name, c.bytes);
    const bool din = c.file_name.ends_with(".din");
    const std::vector<std::string> specs =
        din ? std::vector<std::string>{"size=4KiB,line=64B,assoc=4"}
            : std::vector<std::string>{"size=4KiB,line=64B,assoc=4,layout=morton", "size=4KiB,source=depth"};
    for (const std::string& spec : specs) {
      const auto start = std::chrono::steady_clock::now();
      const testing::CommandRun r = run_rastrace({"replay", path, "--cache", spec, "--format", "csv"});
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (seconds > slowest) slowest = seconds, slowest_name = c.name;
      EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << c.name << " " << spec << ": exit " << r.exit_code << " " << r.err;
      if (r.exit_code == 1) {
        EXPECT_NE(r.err.find(c.file_name), std::string::npos) << c.name << ": " << r.err;
      } else if (r.exit_code == 0) {
        EXPECT_NE(r.out.find("size_bytes"), std::string::npos) << c.name << " " << spec << ": " << r.out << r.err;
      }
      // Generous (a sanitizer build, a loaded machine): the work per case is a few lines.
      EXPECT_LT(seconds, 20.0) << c.name << " " << spec;
    }
  }
  std::printf("slowest case: %s, %.2f s\n", slowest_name.c_str(), slowest);
}

}  // namespace
}  // namespace rastrace
