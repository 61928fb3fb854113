// The small XML tag scanner under the .vtu reader.

#include "engine/io/xml_scanner.h"

#include <gtest/gtest.h>

#include "tests/engine/io/io_test_util.h"

namespace mtcut::engine {
namespace {

std::vector<XmlTag> all_tags(const std::string& text) {
  XmlScanner xml("t.xml", text);
  std::vector<XmlTag> tags;
  XmlTag tag;
  while (xml.next_tag(tag)) tags.push_back(tag);
  return tags;
}

TEST(VtuXmlScanner, HandsOutTagsWithAttributesAndLines) {
  const std::string text =
      "<?xml version=\"1.0\"?>\n<!-- a <comment> -->\n<A x=\"1\" y = 'two' z=\"a&lt;b&amp;&quot;&#65;\">\n"
      "text <![CDATA[ <not a tag> ]]>\n<B/>\n</A>\n";
  const auto tags = all_tags(text);
  ASSERT_EQ(tags.size(), 3u);
  EXPECT_EQ(tags[0].name, "A");
  EXPECT_EQ(tags[0].line, 3u);
  EXPECT_EQ(tags[0].attribute("x"), "1");
  EXPECT_EQ(tags[0].attribute("y"), "two");
  EXPECT_EQ(tags[0].attribute("z"), "a<b&\"A");
  EXPECT_FALSE(tags[0].attribute("w"));
  EXPECT_EQ(text.substr(tags[0].begin, 3), "<A ");
  EXPECT_EQ(text[tags[0].end - 1], '>');
  EXPECT_TRUE(tags[1].self_closing);
  EXPECT_EQ(tags[1].line, 5u);
  EXPECT_TRUE(tags[2].closing);
  EXPECT_EQ(tags[2].name, "A");
}

TEST(VtuXmlScanner, CountsLinesAtAnyOffset) {
  const std::string text = "a\nb\nc\n<X/>";
  XmlScanner xml("t.xml", text);
  EXPECT_EQ(xml.line_at(4), 3u);
  EXPECT_EQ(xml.line_at(0), 1u);  // backwards works too
  EXPECT_EQ(xml.line_at(1000), 4u);
}

TEST(VtuXmlScanner, RejectsMalformedTagsWithTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"\n<A x=\"1\"", "line 2: the file ends inside the tag <A>"},
      {"<A x=1>", "line 1: the value of the attribute x of <A> is not quoted"},
      {"<A x>", "the attribute x of <A> has no value"},
      {"<A x=\"1>", "the value of the attribute x is never closed"},
      {"<A x=\"1\" x=\"2\">", "the attribute x appears twice"},
      {"\n\n<!-- open", "line 3: unterminated comment"},
      {"< A>", "a '<' that does not start a tag"},
      {"</A x=\"1\">", "the end tag </A> has attributes"},
      {"<A / >", "a stray '/'"},
  };
  for (const auto& [text, message] : cases)
    test::expect_input_error([&] { all_tags(text); }, {"t.xml", message});
}

}  // namespace
}  // namespace mtcut::engine
