// The book's build steps that Doxygen cannot do, as plain functions (book_tool.cpp is the
// command line; tests/test_book.cpp tests the functions on deliberately broken input):
//  - values: pages cite measured numbers as @{key}; the chapter programs write "key value"
//    lines (ch::Values, chapters/common.h) and the pages are copied with the keys replaced.
//  - test citations: @test{name} becomes a link to the source line of the TEST_CASE "name"; a
//    name that no test has stops the build, so a citation cannot rot.
//  - the claims index page, generated from the TEST_CASE lines of tests/*.cpp.
//  - reading order: previous/next links on every page, \subpage list on the main page.
//  - the rendered check: literal markup in the text a reader sees, too-wide tables, links to
//    missing files or anchors.
#pragma once


// The pieces, by what they do (each a .h with its .cpp, in the library booktool):
#include "book_pages.h"
#include "book_substitute.h"
#include "book_navigation.h"
#include "book_rendered_check.h"
#include "book_editions.h"
#include "book_answer_scan.h"
#include "book_prose_check.h"
#include "book_reproduce.h"
