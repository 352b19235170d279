// madd::OutputSet: several outputs written all or nothing. A failure while
// staging leaves every target as it was and no temporary behind; a success
// puts every file in place and clears an earlier run's stale files.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "madd/atomic_write.hpp"
#include "madd/error.hpp"

namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("madd-output-set-" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::recursive_directory_iterator(dir)) ++n;
  return n;
}

bool stale(const std::string& name) { return name.rfind("old-", 0) == 0; }

}  // namespace

TEST_SUITE("atomic write") {

TEST_CASE("an output set puts every file and directory in place, and removes stale files") {
  const Scratch s;
  fs::create_directories(s.dir / "parts");
  std::ofstream(s.dir / "parts" / "old-9.txt") << "from an earlier run";
  std::ofstream(s.dir / "parts" / "keep.txt") << "not ours";
  madd::OutputSet set;
  set.add_file(s.path("a.txt"), "alpha");
  set.add_file(s.path("b.txt"), "beta");
  set.add_directory(s.path("parts"), {{"old-1.txt", "one"}, {"old-2.txt", "two"}}, stale);
  set.add_directory(s.path("new/dir/"), {{"x.txt", "x"}});
  set.write();
  CHECK(set.empty());
  CHECK(slurp(s.path("a.txt")) == "alpha");
  CHECK(slurp(s.path("b.txt")) == "beta");
  CHECK(slurp(s.path("parts/old-1.txt")) == "one");
  CHECK(slurp(s.path("parts/old-2.txt")) == "two");
  CHECK_FALSE(fs::exists(s.dir / "parts" / "old-9.txt"));
  CHECK(slurp(s.path("parts/keep.txt")) == "not ours");
  CHECK(slurp(s.path("new/dir/x.txt")) == "x");
  // a.txt b.txt parts parts/{old-1,old-2,keep} new new/dir new/dir/x: nothing else (no temporary).
  CHECK(entries(s.dir) == 9);
}

TEST_CASE("a failure while staging changes no target and leaves no temporary") {
  const Scratch s;
  std::ofstream(s.dir / "a.txt") << "earlier";
  fs::create_directories(s.dir / "parts");
  std::ofstream(s.dir / "parts" / "old-1.txt") << "earlier part";
  const std::size_t before = entries(s.dir);

  SUBCASE("a file in a missing directory") {
    madd::OutputSet set;
    set.add_file(s.path("a.txt"), "new");
    set.add_directory(s.path("parts"), {{"old-1.txt", "new part"}, {"old-2.txt", "new part"}}, stale);
    set.add_file(s.path("missing/z.txt"), "z");
    CHECK_THROWS_AS(set.write(), madd::OutputError);
  }
  SUBCASE("a directory where a file is") {
    madd::OutputSet set;
    set.add_file(s.path("a.txt"), "new");
    set.add_directory(s.path("a.txt/sub"), {{"f", "f"}});
    CHECK_THROWS_AS(set.write(), madd::OutputError);
  }
  SUBCASE("a directory output over an existing file") {
    madd::OutputSet set;
    set.add_directory(s.path("parts"), {{"old-1.txt", "new part"}}, stale);
    set.add_directory(s.path("a.txt"), {{"f", "f"}});
    CHECK_THROWS_AS(set.write(), madd::OutputError);
  }
  CHECK(slurp(s.path("a.txt")) == "earlier");
  CHECK(slurp(s.path("parts/old-1.txt")) == "earlier part");
  CHECK_FALSE(fs::exists(s.dir / "parts" / "old-2.txt"));
  CHECK(entries(s.dir) == before);
}

TEST_CASE("a path named twice in one set is refused before anything is written") {
  const Scratch s;
  madd::OutputSet set;
  set.add_file(s.path("a.txt"), "1");
  CHECK_THROWS_AS(set.add_file(s.path("./a.txt"), "2"), madd::OutputError);
  CHECK_THROWS_AS(set.add_directory(s.path("a.txt"), {}), madd::OutputError);
  CHECK_FALSE(fs::exists(s.dir / "a.txt"));
}

// A file made in pieces while it is written: the pieces in order whatever
// thread makes which, and a failure in any piece leaves nothing.
TEST_CASE("a file made in pieces is the pieces in order, for any thread count") {
  const Scratch s;
  // Pieces of uneven size, so that later ones often finish before earlier
  // ones when threads race.
  const auto piece = [](std::size_t i) {
    std::string text;
    for (std::size_t k = 0; k < (i % 7) * 1000 + 1; ++k) text += static_cast<char>('a' + (i + k) % 26);
    return text + "|" + std::to_string(i) + "\n";
  };
  std::string whole;
  for (std::size_t i = 0; i < 200; ++i) whole += piece(i);
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    CAPTURE(threads);
    madd::OutputSet set;
    set.add_file(s.path("p.txt"), madd::FilePieces{200, piece, threads});
    set.add_file(s.path("empty.txt"), madd::FilePieces{0, piece, threads});
    set.write();
    CHECK(slurp(s.path("p.txt")) == whole);
    CHECK(slurp(s.path("empty.txt")).empty());
    CHECK(entries(s.dir) == 2);  // no temporary left
  }
}

TEST_CASE("a piece that throws writes no file of the set and leaves no temporary") {
  const Scratch s;
  std::ofstream(s.dir / "p.txt") << "earlier";
  const auto piece = [](std::size_t i) -> std::string {
    if (i == 37) throw madd::OutputError("piece 37 failed");
    return std::string(5000, 'x');
  };
  for (const unsigned threads : {1u, 3u}) {
    CAPTURE(threads);
    madd::OutputSet set;
    set.add_file(s.path("q.txt"), "before the pieces");
    set.add_file(s.path("p.txt"), madd::FilePieces{100, piece, threads});
    CHECK_THROWS_WITH_AS(set.write(), doctest::Contains("piece 37 failed"), madd::OutputError);
    CHECK(slurp(s.path("p.txt")) == "earlier");
    CHECK_FALSE(fs::exists(s.dir / "q.txt"));
    CHECK(entries(s.dir) == 1);
  }
}

TEST_CASE("files made in pieces one after another share one pipeline: each its own pieces, all or nothing") {
  // The next file's pieces are made while the last of the one before are
  // written: every file must still get exactly its own pieces, in order;
  // and a failure in a later file (a piece that throws, a directory in the
  // way) must leave the earlier, fully written ones out of place too.
  const Scratch s;
  const auto piece_of = [](char tag) {
    return [tag](std::size_t i) { return std::string(1 + (i * 37) % 3000, tag) + std::to_string(i) + "\n"; };
  };
  const std::size_t counts[] = {5, 0, 1, 64, 3};
  const auto name = [&](std::size_t f) {  // appended: GCC 12 warns (-Wrestrict) on "f" + to_string
    std::string n = "f";
    n += std::to_string(f);
    return s.path(n);
  };
  for (const unsigned threads : {1u, 2u, 3u, 8u}) {
    CAPTURE(threads);
    madd::OutputSet set;
    for (std::size_t f = 0; f < 5; ++f)
      set.add_file(name(f), madd::FilePieces{counts[f], piece_of(char('a' + f)), threads});
    set.write();
    for (std::size_t f = 0; f < 5; ++f) {
      std::string want;
      for (std::size_t i = 0; i < counts[f]; ++i) want += piece_of(char('a' + f))(i);
      CHECK(slurp(name(f)) == want);
    }
    CHECK(entries(s.dir) == 5);
    fs::remove_all(s.dir);
    fs::create_directories(s.dir);
  }
  const auto throwing = [](std::size_t i) -> std::string {
    if (i == 2) throw madd::OutputError("piece 2 of the second file failed");
    return std::string(4000, 'y');
  };
  for (const unsigned threads : {1u, 3u}) {
    CAPTURE(threads);
    madd::OutputSet set;
    set.add_file(s.path("first"), madd::FilePieces{40, piece_of('a'), threads});
    set.add_file(s.path("second"), madd::FilePieces{10, throwing, threads});
    CHECK_THROWS_WITH_AS(set.write(), doctest::Contains("piece 2 of the second file failed"), madd::OutputError);
    CHECK(entries(s.dir) == 0);
    fs::create_directories(s.dir / "second");  // a directory in the way of the second file
    madd::OutputSet blocked;
    blocked.add_file(s.path("first"), madd::FilePieces{40, piece_of('a'), threads});
    blocked.add_file(s.path("second"), madd::FilePieces{10, piece_of('b'), threads});
    CHECK_THROWS_WITH_AS(blocked.write(), doctest::Contains("is a directory"), madd::OutputError);
    CHECK(entries(s.dir) == 1);  // the directory alone
    fs::remove_all(s.dir / "second");
  }
}

}  // TEST_SUITE("atomic write")
