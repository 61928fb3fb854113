// Raw numbers as the binary VTK formats store them, and base64.

#include "engine/io/binary_values.h"

#include <gtest/gtest.h>

#include <cstring>

namespace mtcut::engine {
namespace {

TEST(VtkBinaryValues, KnowsTypeNamesOfBothFormats) {
  EXPECT_EQ(legacy_vtk_type("FLOAT")->size, 4u);
  EXPECT_TRUE(legacy_vtk_type("double")->real);
  EXPECT_EQ(legacy_vtk_type("vtktypeint64")->size, 8u);
  EXPECT_FALSE(legacy_vtk_type("unsigned_int")->is_signed);
  EXPECT_FALSE(legacy_vtk_type("bit"));
  EXPECT_FALSE(legacy_vtk_type("string"));
  EXPECT_EQ(xml_vtk_type("UInt8")->size, 1u);
  EXPECT_TRUE(xml_vtk_type("Float32")->real);
  EXPECT_FALSE(xml_vtk_type("float32"));  // XML names are case-sensitive
  EXPECT_FALSE(xml_vtk_type("Float16"));
}

TEST(VtkBinaryValues, DecodesBothByteOrders) {
  const unsigned char be[4] = {0x3f, 0x80, 0x00, 0x00};  // 1.0f big-endian
  const unsigned char le[4] = {0x00, 0x00, 0x80, 0x3f};
  const ScalarType f32{4, true, true};
  EXPECT_EQ(decode_real(be, f32, true), 1.0);
  EXPECT_EQ(decode_real(le, f32, false), 1.0);
  const unsigned char minus_two[2] = {0xff, 0xfe};
  std::int64_t v = 0;
  ASSERT_TRUE(decode_int(minus_two, ScalarType{2, false, true}, true, v));
  EXPECT_EQ(v, -2);
  ASSERT_TRUE(decode_int(minus_two, ScalarType{2, false, false}, true, v));
  EXPECT_EQ(v, 65534);
  EXPECT_EQ(decode_real(minus_two, ScalarType{2, false, true}, true), -2.0);
  EXPECT_FALSE(decode_int(be, f32, true, v));  // reals are not ids
  const unsigned char huge[8] = {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};
  EXPECT_FALSE(decode_int(huge, ScalarType{8, false, false}, true, v));
  ASSERT_TRUE(decode_int(huge, ScalarType{8, false, true}, true, v));
  EXPECT_EQ(v, -1);
}

TEST(VtkBinaryValues, DecodesBase64WithWhitespaceAndChunks) {
  EXPECT_EQ(*decode_base64("TWFu", 100), "Man");
  EXPECT_EQ(*decode_base64(" TW\nFu\tTQ==", 100), "ManM");
  EXPECT_EQ(*decode_base64("TWE=TWFu", 100), "MaMan");  // a padded chunk, then another
  EXPECT_EQ(*decode_base64("TWFuTWFu", 4), "ManM");      // stops at max_bytes
  EXPECT_EQ(*decode_base64("TWE", 100), "Ma");           // unpadded tail
  std::size_t used = 0;
  EXPECT_EQ(*decode_base64("TWFu####", 3, &used), "Man");  // the rest is not looked at
  EXPECT_EQ(used, 4u);
  EXPECT_FALSE(decode_base64("TW#u", 100));
  EXPECT_FALSE(decode_base64("T===", 100));
  EXPECT_FALSE(decode_base64("TW=u", 100));
  EXPECT_EQ(*decode_base64("", 100), "");
}

}  // namespace
}  // namespace mtcut::engine
