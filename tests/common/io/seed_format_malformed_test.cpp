// Malformed seed text (seed 000 appendix A, SPEC 3): every input is refused with a
// MapFormatError naming the right line and what was expected.
//
// Cases are edits of small valid files whose line numbers are listed below, so that
// each expected line can be checked by eye.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

// A file as a list of lines, edited by 1-based line number.
class Lines {
 public:
  Lines(std::initializer_list<std::string> l) : lines_(l) {}
  Lines set(size_t n, std::string s) const {
    Lines c = *this;
    c.lines_.at(n - 1) = std::move(s);
    return c;
  }
  Lines erase(size_t n) const {
    Lines c = *this;
    c.lines_.erase(c.lines_.begin() + static_cast<long>(n - 1));
    return c;
  }
  Lines erase(size_t first, size_t last) const {  // inclusive
    Lines c = *this;
    c.lines_.erase(c.lines_.begin() + static_cast<long>(first - 1), c.lines_.begin() + static_cast<long>(last));
    return c;
  }
  // The new line becomes line n.
  Lines insert(size_t n, std::string s) const {
    Lines c = *this;
    c.lines_.insert(c.lines_.begin() + static_cast<long>(n - 1), std::move(s));
    return c;
  }
  Lines keep(size_t n) const {
    Lines c = *this;
    c.lines_.resize(n);
    return c;
  }
  Lines append(std::initializer_list<std::string> more) const {
    Lines c = *this;
    c.lines_.insert(c.lines_.end(), more);
    return c;
  }
  std::string str(const char* eol = "\n", bool final_eol = true) const {
    std::string out;
    for (size_t i = 0; i < lines_.size(); ++i) {
      out += lines_[i];
      if (i + 1 < lines_.size() || final_eol) out += eol;
    }
    return out;
  }
  std::string crlf() const { return str("\r\n"); }

 private:
  std::vector<std::string> lines_;
};

// Seed 000 appendix A (obstacle 1) and seed 001 Fig. 2 (the %11 note, obstacle 110).
// The line after the last one, 31, is where the end of file is reported.
const Lines kColumn = {
    "border;",                    //  1
    "-4;58;",                     //  2
    "58;-4;",                     //  3
    "#",                          //  4
    "obstacle;",                  //  5
    "1;1;4;column,A5;",           //  6
    "#",                          //  7
    "4.53;12.10;",                //  8  segment 1
    "7.29;12.10;",                //  9
    "5;1;wall,orange,brick;%11",  // 10
    "#",                          // 11
    "7.29;12.10;",                // 12  segment 2
    "7.29;13.86;",                // 13
    "5;1;wall,orange,brick;",     // 14
    "#",                          // 15
    "7.29;13.86;",                // 16  segment 3
    "4.53;13.86;",                // 17
    "5;1;wall,orange,brick;",     // 18
    "#",                          // 19
    "4.53;13.86;",                // 20  segment 4
    "4.53;12.10;",                // 21
    "5;1;wall,orange,brick;",     // 22
    "#",                          // 23
    "obstacle;",                  // 24
    "110;2;1;wall,A4;",           // 25
    "#",                          // 26
    "-3;0;",                      // 27  segment 1
    "-4;0;",                      // 28
    "1.2;1;wall,grey,cement;",    // 29
    "#",                          // 30
};

// Seed 000 appendix A, obstacle 26: the closing segment (h = 0) first, then the steps,
// oriented the other way, lower as they go away from it.
const Lines kStairs = {
    "border;",                 //  1
    "-4;58;",                  //  2
    "58;-4;",                  //  3
    "#",                       //  4
    "obstacle;",               //  5
    "26;5;4;step,FIBsquare;",  //  6
    "#",                       //  7
    "34.65;40.72;",            //  8  closing segment
    "57.5;40.72;",             //  9
    "0;1;wall,greycement;",    // 10
    "#",                       // 11
    "57.5;41.02;",             // 12  step 2
    "34.65;41.02;",            // 13
    "2;1;wall,greycement;",    // 14
    "#",                       // 15
    "57.5;41.32;",             // 16  step 3
    "34.65;41.32;",            // 17
    "1.8;1;wall,greycement;",  // 18
    "#",                       // 19
    "57.5;41.62;",             // 20  step 4
    "34.65;41.62;",            // 21
    "1.6;1;wall,greycement;",  // 22
    "#",                       // 23
};

// A ramp (common/map/ramp.h): rising 0.1 m per metre along x from the floor at x = 10.
const Lines kRamp = {
    "border;",                                          //  1
    "-4;58;",                                           //  2
    "58;-4;",                                           //  3
    "#",                                                //  4
    "obstacle;",                                        //  5
    "40;6;4;ramp,concrete,normal=-0.1:0:1,foot=10:5;",  //  6
    "#",                                                //  7
    "10;5;",                                            //  8
    "20;5;",                                            //  9
    "0;0;ramp;",                                        // 10
    "#",                                                // 11
    "20;5;",                                            // 12
    "20;10;",                                           // 13
    "0;0;ramp;",                                        // 14
    "#",                                                // 15
    "20;10;",                                           // 16
    "10;10;",                                           // 17
    "0;0;ramp;",                                        // 18
    "#",                                                // 19
    "10;10;",                                           // 20
    "10;5;",                                            // 21
    "0;0;ramp;",                                        // 22
    "#",                                                // 23
};

std::string ramp_header(const std::string& semantic) { return "40;6;4;" + semantic + ";"; }

struct MalformedCase {
  std::string name;
  std::string text;
  size_t expected_line;
  std::string expected_message_substring;
};

std::ostream& operator<<(std::ostream& os, const MalformedCase& c) { return os << c.name; }

std::vector<MalformedCase> malformed_cases() {
  const Lines& c = kColumn;
  const std::string g = "5;1;wall,orange,brick;";  // a segment's 'h;inOut;semantic;' line
  std::vector<MalformedCase> v = {
      // --- file structure ---------------------------------------------------------
      {"empty_file", "", 1, "expected 'border;', got end of file"},
      {"only_blank_lines", "\n  \n\t\n", 4, "expected 'border;', got end of file"},
      {"missing_border_keyword", c.erase(1).str(), 1, "expected 'border;', got '-4;58;'"},
      {"border_keyword_without_semicolon", c.set(1, "border").str(), 1, "expected 'border;', got 'border'"},
      {"border_keyword_capitalised", c.set(1, "Border;").str(), 1, "expected 'border;', got 'Border;'"},
      {"border_truncated_after_first_corner", c.keep(2).str(), 3, "expected 'mx4;my4;', got end of file"},
      {"border_line_one_field", c.set(2, "-4;").str(), 2, "expected 2 fields 'mx1;my1;', got 1 in '-4;'"},
      {"border_line_three_fields", c.set(3, "58;-4;0;").str(), 3, "expected 2 fields 'mx4;my4;', got 3"},
      {"border_line_missing_final_semicolon", c.set(2, "-4;58").str(), 2,
       "expected 'mx1;my1;' (every field ends with ';'), got '-4;58'"},
      {"border_not_a_number", c.set(2, "-4;abc;").str(), 2, "expected a number for my1, got 'abc'"},
      {"border_hex_number", c.set(3, "0x10;-4;").str(), 3, "expected a number for mx4, got '0x10'"},
      {"border_nan", c.set(2, "nan;58;").str(), 2, "expected a finite number for mx1, got 'nan'"},
      {"border_beyond_max_coordinate", c.set(3, "1e8;-4;").str(), 3, "expected |mx4| <= 1e+07, got '1e8'"},
      {"border_inverted_in_x", c.set(2, "58;58;").set(3, "-4;-4;").str(), 3,
       "expected border upper-left then lower-right (mx1 < mx4 and my1 > my4), got (58;58) and (-4;-4)"},
      {"border_inverted_in_y", c.set(2, "-4;-4;").set(3, "58;58;").str(), 3,
       "expected border upper-left then lower-right (mx1 < mx4 and my1 > my4), got (-4;-4) and (58;58)"},
      {"border_equal_corners", c.set(2, "5;5;").set(3, "5;5;").str(), 3,
       "expected border upper-left then lower-right (mx1 < mx4 and my1 > my4), got (5;5) and (5;5)"},
      {"border_without_hash_then_eof", c.keep(3).str(), 4, "expected '#', got end of file"},
      // Without a final newline the end of file is on the last line, not after it.
      {"border_without_hash_then_eof_no_final_newline", c.keep(3).str("\n", false), 3,
       "expected '#', got end of file"},
      {"missing_hash_after_border", c.erase(4).str(), 4, "expected '#', got 'obstacle;'"},
      {"misspelled_obstacle_keyword", c.set(5, "obstacles;").str(), 5,
       "expected 'obstacle;' or end of file, got 'obstacles;'"},
      {"garbage_after_last_obstacle", c.append({"end;"}).str(), 31,
       "expected 'obstacle;' or end of file, got 'end;'"},
      {"garbage_after_last_obstacle_without_final_newline", c.append({"x"}).str("\n", false), 31,
       "expected 'obstacle;' or end of file, got 'x'"},

      // --- obstacle header ----------------------------------------------------------
      {"obstacle_keyword_then_eof", c.keep(5).str(), 6, "expected 'id;ST;NS;semantic;', got end of file"},
      {"header_too_few_fields", c.set(6, "1;1;4;").str(), 6,
       "expected 4 fields 'id;ST;NS;semantic;', got 3 in '1;1;4;'"},
      {"header_too_many_fields", c.set(6, "1;1;4;column;A5;").str(), 6,
       "expected 4 fields 'id;ST;NS;semantic;', got 5"},
      {"header_missing_final_semicolon", c.set(6, "1;1;4;column,A5").str(), 6,
       "expected 'id;ST;NS;semantic;' (every field ends with ';'), got '1;1;4;column,A5'"},
      {"id_not_an_integer", c.set(6, "one;1;4;column,A5;").str(), 6, "expected obstacle id (an integer), got 'one'"},
      {"id_beyond_int", c.set(6, "2147483648;1;4;column,A5;").str(), 6,
       "expected obstacle id (an integer), got '2147483648'"},
      {"shape_type_0", c.set(6, "1;0;4;column,A5;").str(), 6,
       "expected shape type ST in 1..6 (an integer), got '0'"},
      {"shape_type_7", c.set(6, "1;7;4;column,A5;").str(), 6,
       "expected shape type ST in 1..6 (an integer), got '7'"},
      {"shape_type_not_integer", c.set(6, "1;1.5;4;column,A5;").str(), 6,
       "expected shape type ST in 1..6 (an integer), got '1.5'"},
      {"segment_count_zero", c.set(6, "1;1;0;column,A5;").str(), 6,
       "expected segment count NS in 1..10000000 (an integer), got '0'"},
      {"segment_count_negative", c.set(6, "1;1;-4;column,A5;").str(), 6,
       "expected segment count NS in 1..10000000 (an integer), got '-4'"},
      {"segment_count_not_a_number", c.set(6, "1;1;four;column,A5;").str(), 6,
       "expected segment count NS in 1..10000000 (an integer), got 'four'"},
      // The message claims "NS >= 1" of a value that is >= 1 (the real limit is 10 000 000);
      // only the line and the value are checked here, see the report.
      {"segment_count_beyond_limit", c.set(6, "1;1;99999999999;column,A5;").str(), 6, "got '99999999999'"},
      {"missing_hash_after_obstacle_header", c.erase(7).str(), 7, "expected '#', got '4.53;12.10;'"},

      // --- segment count NS -----------------------------------------------------------
      {"fewer_segments_than_ns_then_next_obstacle", c.erase(16, 23).str(), 16,
       "expected segment 3/4 of obstacle 1 ('ax;ay;'), got 'obstacle;' (NS says 4, found 2)"},
      {"fewer_segments_than_ns_then_eof", c.keep(15).str(), 16,
       "expected segment 3/4 of obstacle 1 ('ax;ay;'), got end of file (NS says 4, found 2)"},
      {"more_segments_than_ns", c.append({"-4;0;", "-4;1;", "1.2;1;wall,grey,cement;", "#"}).str(), 31,
       "expected 'obstacle;' or end of file, got '-4;0;'"},

      // --- segment lines ---------------------------------------------------------------
      {"missing_hash_after_segment", c.erase(11).str(), 11, "expected '#', got '7.29;12.10;'"},
      {"missing_hash_after_last_segment_then_eof", c.keep(29).str(), 30, "expected '#', got end of file"},
      {"segment_truncated_after_a", c.keep(8).str(), 9,
       "expected 'bx;by; of segment 1/4 of obstacle 1', got end of file"},
      {"segment_a_three_fields", c.set(8, "4.53;12.10;0;").str(), 8,
       "expected 2 fields 'ax;ay; of segment 1/4 of obstacle 1', got 3"},
      {"segment_b_one_field", c.set(13, "7.29;").str(), 13,
       "expected 2 fields 'bx;by; of segment 2/4 of obstacle 1', got 1"},
      {"segment_b_missing_final_semicolon", c.set(9, "7.29;12.10").str(), 9,
       "expected 'bx;by; of segment 1/4 of obstacle 1' (every field ends with ';'), got '7.29;12.10'"},
      {"segment_h_line_too_few_fields", c.set(10, "5;1;").str(), 10,
       "expected 3 fields 'h;inOut;semantic; of segment 1/4 of obstacle 1', got 2 in '5;1;'"},
      {"segment_h_line_too_many_fields", c.set(14, "5;1;wall;brick;").str(), 14,
       "expected 3 fields 'h;inOut;semantic; of segment 2/4 of obstacle 1', got 4"},
      {"segment_h_line_missing", c.erase(10).str(), 10,
       "expected 'h;inOut;semantic; of segment 1/4 of obstacle 1' (every field ends with ';'), got '#'"},
      {"ax_not_a_number", c.set(8, "abc;12.10;").str(), 8, "expected a number for ax, got 'abc'"},
      {"ax_empty", c.set(8, ";12.10;").str(), 8, "expected a number for ax, got ''"},
      {"ax_decimal_comma", c.set(8, "4,53;12.10;").str(), 8, "expected a number for ax, got '4,53'"},
      {"ax_hex", c.set(8, "0x10;12.10;").str(), 8, "expected a number for ax, got '0x10'"},
      {"ax_inf", c.set(8, "inf;12.10;").str(), 8, "expected a finite number for ax, got 'inf'"},
      {"ay_nan", c.set(8, "4.53;nan;").str(), 8, "expected a finite number for ay, got 'nan'"},
      {"bx_minus_inf", c.set(9, "-inf;12.10;").str(), 9, "expected a finite number for bx, got '-inf'"},
      {"by_out_of_double_range", c.set(9, "7.29;1e400;").str(), 9, "expected a number within double range for by, got '1e400'"},
      // Underflows to 0: refused, but the message calls it not finite; see the report.
      {"ax_underflow", c.set(8, "1e-400;12.10;").str(), 8, "for ax, got '1e-400'"},
      {"ax_beyond_max_coordinate", c.set(8, "2e7;12.10;").str(), 8, "expected |ax| <= 1e+07, got '2e7'"},
      {"by_beyond_max_coordinate", c.set(9, "7.29;-10000000.5;").str(), 9,
       "expected |by| <= 1e+07, got '-10000000.5'"},
      {"zero_length_segment", c.set(9, "4.53;12.10;").str(), 9, "expected a segment of non-zero length, got b = a"},
      {"segment_a_outside_border", c.set(8, "-5;12.10;").str(), 8,
       "expected segment 1/4 of obstacle 1 to start inside the border, got it outside"},
      {"segment_b_outside_border", c.set(9, "7.29;60;").str(), 9,
       "expected segment 1/4 of obstacle 1 to end inside the border"},
      {"height_negative", c.set(10, "-1;1;wall;").str(), 10, "expected height h in 0..1000 m, got -1"},
      {"height_above_max", c.set(10, "1000.5;1;wall;").str(), 10, "expected height h in 0..1000 m, got 1000.5"},
      {"height_nan", c.set(10, "nan;1;wall;").str(), 10, "expected a finite number for h, got 'nan'"},
      {"in_out_2", c.set(10, "5;2;wall;").str(), 10, "expected inOut 0 or 1 (an integer), got '2'"},
      {"in_out_letter", c.set(10, "5;x;wall;").str(), 10, "expected inOut 0 or 1 (an integer), got 'x'"},
      {"in_out_negative", c.set(14, "5;-1;wall;").str(), 14, "expected inOut 0 or 1 (an integer), got '-1'"},

      // --- obstacle ids -------------------------------------------------------------------
      {"duplicate_obstacle_id", c.set(25, "1;2;1;wall,A4;").str(), 25,
       "expected a unique obstacle id, got id 1 again"},

      // --- semantic strings and notes --------------------------------------------------------
      {"obstacle_semantic_byte_ff", c.set(6, "1;1;4;column\xff;").str(), 6,
       "expected UTF-8 text in obstacle semantic, got byte 0xFF at offset 6"},
      {"obstacle_semantic_overlong_slash", c.set(6, "1;1;4;\xc0\xaf;").str(), 6,
       "expected UTF-8 text in obstacle semantic, got byte 0xC0 at offset 0"},
      {"obstacle_semantic_control_character", c.set(6, "1;1;4;col\x01umn;").str(), 6,
       "expected printable text in obstacle semantic, got a control character at offset 3"},
      {"obstacle_semantic_hash", c.set(6, "1;1;4;column#A5;").str(), 6,
       "expected obstacle semantic without ';', '#' or '%'"},
      {"segment_semantic_byte_ff", c.set(10, "5;1;wall,\xff;").str(), 10,
       "expected UTF-8 text in segment semantic, got byte 0xFF at offset 5"},
      {"segment_semantic_overlong", c.set(10, "5;1;\xc0\xaf;").str(), 10,
       "expected UTF-8 text in segment semantic, got byte 0xC0 at offset 0"},
      {"segment_semantic_lone_continuation_byte", c.set(14, "5;1;wall\x80;").str(), 14,
       "expected UTF-8 text in segment semantic, got byte 0x80 at offset 4"},
      {"segment_semantic_truncated_sequence", c.set(14, "5;1;caf\xc3;").str(), 14,
       "expected UTF-8 text in segment semantic, got byte 0xC3 at offset 3"},
      {"segment_semantic_utf16_surrogate", c.set(14, "5;1;\xed\xa0\x80;").str(), 14,
       "expected UTF-8 text in segment semantic, got byte 0xED at offset 0"},
      {"segment_semantic_tab", c.set(18, "5;1;wall\tbrick;").str(), 18,
       "expected printable text in segment semantic, got a control character at offset 4"},
      {"segment_semantic_delete", c.set(18, "5;1;wall\x7f;").str(), 18,
       "expected printable text in segment semantic, got a control character at offset 4"},
      {"segment_semantic_hash", c.set(18, "5;1;wall#3;").str(), 18,
       "expected segment semantic without ';', '#' or '%'"},
      {"segment_semantic_too_long", c.set(18, "5;1;" + std::string(1025, 'w') + ";").str(), 18,
       "expected segment semantic of at most 1024 bytes, got 1025"},
      {"segment_note_control_character", c.set(10, g + "%bad\x01note").str(), 10,
       "expected printable text in segment note, got a control character at offset 3"},
      {"segment_note_byte_ff", c.set(10, g + "%11\xff").str(), 10,
       "expected UTF-8 text in segment note, got byte 0xFF at offset 2"},

      // --- '%' comments anywhere but after 'h;inOut;semantic;' -------------------------------
      {"comment_on_border_keyword_line", c.set(1, "border; %map of FIB").str(), 1,
       "expected no '%' comment on this line (only after 'h;inOut;semantic;'), got '%map of FIB'"},
      {"comment_on_border_corner_line", c.set(2, "-4;58; %upper left").str(), 2,
       "expected no '%' comment on this line (only after 'h;inOut;semantic;'), got '%upper left'"},
      {"comment_on_hash_line", c.set(7, "# %separator").str(), 7,
       "expected no '%' comment on this line (only after 'h;inOut;semantic;'), got '%separator'"},
      {"comment_on_obstacle_header_line", c.set(6, "1;1;4;column,A5;%12").str(), 6,
       "expected no '%' comment on this line (only after 'h;inOut;semantic;'), got '%12'"},
      {"comment_on_segment_a_line", c.set(8, "4.53;12.10; %a").str(), 8,
       "expected no '%' comment on this line (only after 'h;inOut;semantic;'), got '%a'"},
      {"comment_on_obstacle_keyword_line", c.set(5, "obstacle; %column").str(), 5,
       "expected no '%' comment on this line"},
      {"full_line_comment_among_segment_lines", c.insert(9, "% the wall facing the street").str(), 9,
       "expected no '%' comment on a line of its own (only after 'h;inOut;semantic;'), got '% the wall facing"},
      {"full_line_comment_at_top", c.insert(1, "% exported by the GIS").str(), 1,
       "expected no '%' comment on a line of its own"},
      {"full_line_comment_after_last_obstacle", c.append({"% end of map"}).str(), 31,
       "expected no '%' comment on a line of its own"},

      // --- shapes: closed and open chains ---------------------------------------------------------
      {"closed_polygon_not_closed", c.set(21, "4.53;12.5;").str(), 6,
       "obstacle 1: expected shape type 1 (closed polygon) to close: last segment should end at (4.53;12.1), "
       "got (4.53;12.5)"},
      {"closed_polygon_gap_between_segments", c.set(12, "7.3;12.10;").str(), 6,
       "obstacle 1: expected shape type 1 (closed polygon) segment 2 to start where segment 1 ends (7.29;12.1), "
       "got (7.3;12.1)"},
      {"closed_polygon_two_segments",
       c.set(25, "110;1;2;wall,A4;").append({"-4;0;", "-3;0;", "1.2;1;wall,grey,cement;", "#"}).str(), 25,
       "obstacle 110: expected at least 3 segments in a shape type 1 (closed polygon), got 2"},
      {"closed_curved_one_segment", c.set(25, "110;3;1;wall,A4;").str(), 25,
       "obstacle 110: expected at least 3 segments in a shape type 3 (closed curved), got 1"},
      {"open_polygon_gap_between_segments",
       c.set(25, "110;2;2;wall,A4;").append({"-3.5;1;", "-3;1;", "1.2;1;wall,grey,cement;", "#"}).str(), 25,
       "obstacle 110: expected shape type 2 (open polygon) segment 2 to start where segment 1 ends (-4;0), "
       "got (-3.5;1)"},

      // --- stairs (ST 5) ---------------------------------------------------------------------------
      {"stairs_without_closing_segment", kStairs.set(10, "2.2;1;wall,greycement;").str(), 6,
       "obstacle 26: expected a closing segment with h = 0 in stairs, got none"},
      {"stairs_with_two_closing_segments", kStairs.set(22, "0;1;wall,greycement;").str(), 6,
       "obstacle 26: expected one closing segment with h = 0 in stairs, got segments 1 and 4"},
      {"stairs_only_closing_segment", kStairs.set(6, "26;5;1;step,FIBsquare;").keep(11).str(), 6,
       "obstacle 26: expected at least one step (h > 0) besides the closing segment, got none"},
      {"stairs_step_parallel_not_antiparallel", kStairs.set(16, "34.65;41.32;").set(17, "57.5;41.32;").str(), 6,
       "obstacle 26: expected step 3 antiparallel to the closing segment 1, got direction ("},
      {"stairs_step_slanted", kStairs.set(16, "57.5;41.40;").str(), 6,
       "obstacle 26: expected step 3 antiparallel to the closing segment 1, got direction ("},
      {"stairs_heights_not_growing_towards_closing_segment", kStairs.set(18, "2.5;1;wall,greycement;").str(), 6,
       "obstacle 26: expected step heights to grow towards the closing segment, got 2.5 m at 0.6"},
      {"stairs_step_behind_closing_segment", kStairs.set(20, "57.5;40.42;").set(21, "34.65;40.42;").str(), 6,
       "obstacle 26: expected step 4 on the steps' side of the closing segment, got distance -0.29"},

      // --- ramps (ST 6) ------------------------------------------------------------------------------
      {"ramp_segment_with_height", kRamp.set(14, "0.5;0;ramp;").str(), 6,
       "obstacle 40: expected null height on ramp segment 2, got 0.5"},
      {"ramp_without_normal_token", kRamp.set(6, ramp_header("ramp,concrete,foot=10:5")).str(), 6,
       "obstacle 40: expected 'normal=NX:NY:NZ' in the ramp's semantic string, got 'ramp,concrete,foot=10:5'"},
      {"ramp_without_foot_token", kRamp.set(6, ramp_header("ramp,concrete,normal=-0.1:0:1")).str(), 6,
       "obstacle 40: expected 'foot=X:Y' in the ramp's semantic string, got 'ramp,concrete,normal=-0.1:0:1'"},
      {"ramp_normal_horizontal", kRamp.set(6, ramp_header("ramp,normal=-0.1:0:0,foot=10:5")).str(), 6,
       "obstacle 40: expected a ramp normal pointing up (NZ > 0), got NZ = 0"},
      {"ramp_normal_pointing_down", kRamp.set(6, ramp_header("ramp,normal=0.1:0:-1,foot=10:5")).str(), 6,
       "obstacle 40: expected a ramp normal pointing up (NZ > 0), got NZ = -1"},
      {"ramp_normal_two_numbers", kRamp.set(6, ramp_header("ramp,normal=0:1,foot=10:5")).str(), 6,
       "obstacle 40: expected ramp token 'normal=NX:NY:NZ' (3 numbers), got 'normal=0:1'"},
      {"ramp_normal_nan", kRamp.set(6, ramp_header("ramp,normal=nan:0:1,foot=10:5")).str(), 6,
       "obstacle 40: expected ramp token 'normal=NX:NY:NZ' with finite numbers, got 'normal=nan:0:1'"},
      {"ramp_surface_below_floor", kRamp.set(6, ramp_header("ramp,normal=-0.1:0:1,foot=15:5")).str(), 6,
       "obstacle 40: expected the ramp surface on or above the floor at every vertex, got -0.5 m at (10;5)"},

      // --- line numbers with CRLF and blank lines -------------------------------------------------------
      {"crlf_bad_number", c.set(9, "7.29;abc;").crlf(), 9, "expected a number for by, got 'abc'"},
      {"crlf_missing_hash_then_eof", c.keep(29).crlf(), 30, "expected '#', got end of file"},
      {"crlf_shape_error", c.set(21, "4.53;12.5;").crlf(), 6, "expected shape type 1 (closed polygon) to close"},
      {"blank_lines_before_error", c.insert(1, "").insert(1, "   ").insert(6, "\t").set(11, "4.53;nan;").str(), 11,
       "expected a finite number for ay, got 'nan'"},
      // Two blank lines before 'obstacle;' and one between a segment's 'bx;by;' and
      // 'h;inOut;semantic;' lines: the latter, line 10 of kColumn, becomes line 13.
      {"crlf_blank_lines_before_error", c.insert(5, "").insert(5, "\t").insert(12, " ").set(13, "5;2;wall;").crlf(), 13,
       "expected inOut 0 or 1 (an integer), got '2'"},
  };
  return v;
}

class SeedMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(SeedMalformed, RefusedWithLineAndExpectation) {
  const MalformedCase& tc = GetParam();
  const std::string file = "malformed/" + tc.name + ".txt";
  try {
    Map m = read_seed(tc.text, file);
    ADD_FAILURE() << "accepted, with " << m.obstacles.size() << " obstacles"
;
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.line(), tc.expected_line) << e.what();
    EXPECT_NE(e.message().find(tc.expected_message_substring), std::string::npos)
        << "message: " << e.message() << "\nexpected to contain: " << tc.expected_message_substring
;
    const std::string prefix = file + ":" + std::to_string(e.line()) + ": ";
    EXPECT_EQ(std::string(e.what()).substr(0, prefix.size()), prefix) << e.what();
    EXPECT_EQ(std::string(e.what()), prefix + e.message());
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something else than MapFormatError: " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(SeedFormat, SeedMalformed, ::testing::ValuesIn(malformed_cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& info) { return info.param.name; });

// The table really holds distinct inputs (and distinct names, which gtest also checks).
TEST(SeedMalformedTable, CasesAreDistinctAndMany) {
  const auto cases = malformed_cases();
  std::set<std::string> texts;
  for (const auto& c : cases) texts.insert(c.text);
  EXPECT_EQ(texts.size(), cases.size());
  EXPECT_GE(cases.size(), 45u);
}

// The three bases the cases are edited from are themselves valid.
TEST(SeedMalformedTable, BasesAreValid) {
  EXPECT_NO_THROW(read_seed(kColumn.str()));
  EXPECT_NO_THROW(read_seed(kColumn.crlf()));
  EXPECT_NO_THROW(read_seed(kStairs.str()));
  EXPECT_NO_THROW(read_seed(kRamp.str()));
}

// SPEC 5.4: a window cuts obstacles at its edge, so a closed polygon may arrive as an
// open chain; MapKind::Window accepts it, a whole map does not.
TEST(SeedMalformedWindow, CutClosedPolygonAcceptedOnlyInWindow) {
  // The column of kColumn cut at x = 6: segments 2 and 3 lose their right part.
  const std::string cut = Lines{
      "border;", "-4;58;", "6;-4;", "#",                              //
      "obstacle;", "1;1;3;column,A5;", "#",                           //
      "6;13.86;", "4.53;13.86;", "5;1;wall,orange,brick;", "#",       //
      "4.53;13.86;", "4.53;12.10;", "5;1;wall,orange,brick;", "#",    //
      "4.53;12.10;", "6;12.10;", "5;1;wall,orange,brick;%11", "#",    //
  }.str();
  Map w;
  ASSERT_NO_THROW(w = read_seed(cut, "window.txt", MapKind::Window));
  ASSERT_EQ(w.obstacles.size(), 1u);
  EXPECT_EQ(w.obstacles[0].type, ShapeType::ClosedPolygon);
  EXPECT_EQ(w.obstacles[0].segments.size(), 3u);
  EXPECT_EQ(w.obstacles[0].segments[2].note, "11");
  try {
    read_seed(cut, "window.txt", MapKind::Whole);
    ADD_FAILURE() << "a whole map accepted an open closed polygon";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_NE(e.message().find("expected shape type 1 (closed polygon) to close"), std::string::npos) << e.what();
  }
}

// A window is still refused for what is wrong in any map: per-segment rules and ramps.
TEST(SeedMalformedWindow, WindowStillChecksSegmentsAndRamps) {
  try {
    read_seed(kColumn.set(9, "7.29;nan;").str(), "w.txt", MapKind::Window);
    ADD_FAILURE() << "accepted a NaN in a window";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.line(), 9u);
  }
  try {
    read_seed(kRamp.set(6, ramp_header("ramp,concrete")).str(), "w.txt", MapKind::Window);
    ADD_FAILURE() << "accepted a ramp without its surface in a window";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_NE(e.message().find("expected 'normal=NX:NY:NZ'"), std::string::npos) << e.what();
  }
}

TEST(SeedMalformedFile, UnreadableFileNamesThePath) {
  const std::string path = "/nonexistent/fleetmap/seed.txt";
  try {
    read_seed_file(path);
    ADD_FAILURE() << "read a file that does not exist";
  } catch (const IoError& e) {  // not malformed: an I/O failure (README "Exit codes")
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected a readable file"), std::string::npos) << e.what();
  }
}

TEST(SeedMalformedFile, ErrorInFileNamesPathAndLine) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("seed_format_malformed_test_" + std::to_string(std::random_device{}()) + ".txt");
  {
    std::ofstream out(path, std::ios::binary);
    out << kColumn.set(13, "7.29;13.86").crlf();
  }
  try {
    read_seed_file(path.string());
    ADD_FAILURE() << "accepted a malformed file";
  } catch (const MapFormatError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), 13u);
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ":13: expected 'bx;by; of segment 2/4 of obstacle 1'", 0),
              0u)
        << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace fleetmap
