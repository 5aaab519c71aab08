// The pictures of report.html: the rasteriser, the PNG encoder, the view, and the page's text.
#include <gtest/gtest.h>

#include "report/markup.hpp"
#include "report/picture.hpp"
#include "report/png_reader.hpp"

namespace vorocrust::report {
namespace {

constexpr Rgb kWhite{255, 255, 255}, kRed{255, 0, 0}, kBlue{0, 0, 255}, kBlack{0, 0, 0};

TEST(Picture, FillsTheTriangleAndNothingElse) {
  Picture picture(20, 10, kWhite);
  picture.draw_triangle({Point(0, 0, 1), Point(10, 0, 1), Point(0, 10, 1)}, kRed);
  EXPECT_EQ(picture.pixel(1, 1), kRed);
  EXPECT_EQ(picture.pixel(8, 0), kRed);
  EXPECT_EQ(picture.pixel(9, 9), kWhite);   // beyond the hypotenuse
  EXPECT_EQ(picture.pixel(15, 2), kWhite);  // beside it
  // Either orientation fills.
  picture.draw_triangle({Point(12, 0, 1), Point(12, 10, 1), Point(20, 0, 1)}, kBlue);
  EXPECT_EQ(picture.pixel(13, 2), kBlue);
}

TEST(Picture, TheNearerTriangleWinsWhateverTheOrder) {
  for (bool near_first : {false, true}) {
    Picture picture(10, 10, kWhite);
    const std::array<Point, 3> near = {Point(0, 0, 1), Point(10, 0, 1), Point(0, 10, 1)};
    const std::array<Point, 3> far = {Point(0, 0, 5), Point(10, 0, 5), Point(0, 10, 5)};
    if (near_first) {
      picture.draw_triangle(near, kRed);
      picture.draw_triangle(far, kBlue);
    } else {
      picture.draw_triangle(far, kBlue);
      picture.draw_triangle(near, kRed);
    }
    EXPECT_EQ(picture.pixel(2, 2), kRed) << "near drawn first: " << near_first;
    // After clear_depth, what follows is in front.
    picture.clear_depth();
    picture.draw_triangle(far, kBlue);
    EXPECT_EQ(picture.pixel(2, 2), kBlue);
  }
}

TEST(Picture, LinesShowOverTheirFacesAndAreClipped) {
  Picture picture(10, 10, kWhite);
  picture.draw_triangle({Point(0, 0, 2), Point(10, 0, 2), Point(0, 10, 2)}, kRed);
  picture.draw_line(Point(0, 0.5, 2), Point(6, 0.5, 2), kBlack);
  EXPECT_EQ(picture.pixel(3, 0), kBlack);
  // A line far past the picture costs no more than its visible part and draws it.
  picture.draw_line(Point(-1e12, 5.5, 0), Point(1e12, 5.5, 0), kBlue);
  EXPECT_EQ(picture.pixel(0, 5), kBlue);
  EXPECT_EQ(picture.pixel(9, 5), kBlue);
  // A triangle far larger than the picture still fills it (no int overflow on its corners).
  Picture big(10, 10, kWhite);
  big.draw_triangle({Point(-3e9, -3e9, 0), Point(3e9, -3e9, 0), Point(0, 3e9, 0)}, kBlue);
  EXPECT_EQ(big.pixel(5, 5), kBlue);
  // Degenerate and non-finite input draws nothing and does not throw.
  picture.draw_triangle({Point(1, 1, 0), Point(2, 2, 0), Point(3, 3, 0)}, kBlue);
  picture.draw_line(Point(0, 0, 0), Point(std::nan(""), 1, 0), kBlue);
  EXPECT_EQ(picture.pixel(2, 2), kRed);
}

TEST(Picture, PngIsAValidFileHoldingThePixels) {
  Picture picture(7, 3, kWhite);
  picture.draw_triangle({Point(0, 0, 0), Point(7, 0, 0), Point(0, 3, 0)}, kRed);
  const std::string png = encode_png(picture);
  const test::DecodedPng decoded = test::decode_png(png);  // checks signature, chunks and CRCs
  EXPECT_EQ(decoded.chunks, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
  EXPECT_EQ(decoded.width, 7);
  EXPECT_EQ(decoded.height, 3);
  EXPECT_EQ(decoded.rgb, picture.rgb());
}

TEST(View, FramesTheBoxAndShadesBothSides) {
  const View view(Point(-1, -2, -3), Point(1, 2, 3), Point(0, 0, 1), Point(0, 1, 0), 200, 100, 10);
  // The centre lands mid-picture; the y extent (4) fills the height less the margins.
  const Point centre = view.to_screen(Point(0, 0, 0));
  EXPECT_DOUBLE_EQ(centre.x(), 100);
  EXPECT_DOUBLE_EQ(centre.y(), 50);
  const Point top = view.to_screen(Point(0, 2, 0));
  EXPECT_NEAR(top.y(), 10, 1e-9);  // up is up the picture
  EXPECT_LT(view.to_screen(Point(0, 0, -3)).z(), view.to_screen(Point(0, 0, 3)).z());  // nearer is smaller
  const double facing = view.shade(Point(0, 0, -1)), away = view.shade(Point(0, 0, 1));
  EXPECT_DOUBLE_EQ(facing, away);
  EXPECT_GT(facing, 0.35);
  EXPECT_LE(facing, 1.0);
}

TEST(Markup, Base64MatchesTheStandardsVectors) {
  // RFC 4648, section 10.
  EXPECT_EQ(base64(std::string_view("")), "");
  EXPECT_EQ(base64(std::string_view("f")), "Zg==");
  EXPECT_EQ(base64(std::string_view("fo")), "Zm8=");
  EXPECT_EQ(base64(std::string_view("foo")), "Zm9v");
  EXPECT_EQ(base64(std::string_view("foob")), "Zm9vYg==");
  EXPECT_EQ(base64(std::string_view("fooba")), "Zm9vYmE=");
  EXPECT_EQ(base64(std::string_view("foobar")), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string_view("\xff\xfe", 2)), "//4=");
}

TEST(Markup, EscapesAndNumbersAreSafeInAnyLocale) {
  EXPECT_EQ(escape_markup("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
  EXPECT_EQ(locale_free_number(0.5, std::chars_format::fixed, 2), "0.50");
  EXPECT_EQ(locale_free_number(12345.678, std::chars_format::general, 4), "1.235e+04");
  EXPECT_EQ(locale_free_number(1e100, std::chars_format::fixed, 3), "1e+100");
}

TEST(Picture, RegionColoursDifferAndOutsideIsGrey) {
  EXPECT_EQ(region_colour(0), (Rgb{170, 170, 170}));
  for (int a = 1; a <= 12; ++a) {
    for (int b = a + 1; b <= 12; ++b) EXPECT_NE(region_colour(a), region_colour(b)) << a << " " << b;
  }
  EXPECT_EQ(scaled(Rgb{100, 200, 250}, 0.5), (Rgb{50, 100, 125}));
  EXPECT_EQ(scaled(Rgb{100, 200, 250}, 2), (Rgb{200, 255, 255}));
}

}  // namespace
}  // namespace vorocrust::report
