// A POV-Ray source file held in memory, and its raw tokens: words, numbers, strings and
// punctuation as POV-Ray's tokenizer reads them, with no meaning given yet (that is the
// token stream's work, token_stream.h). Tokens are read on demand, so that an error late in
// a file is found only when POV-Ray would find it, and kept, so that a #while loop or a
// macro body read again costs no second reading.
#pragma once

#include "scenegraph/source_loc.h"

#include <cstddef>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lucent::sdl {

enum class RawKind { Word, Number, String, Punct, End };

struct RawToken {
  // Word, Number, Punct: the characters as written, a view into the file's text. String: the
  // characters between the quotes, `\"` read as `"` and every other escape kept for later
  // (a file name is read without them). Punct is one of { } @ & ` \ | : , - $ = != ! ^ <= <
  // ( [ % + ? >= > ) ] ; ' / * ~ # . The view lives as long as its SourceFile.
  std::string_view text;
  double number = 0;
  int line = 0, col = 0;
  int keyword = -1;  // Word: its entry in keywords.h, or -1 for an identifier
  RawKind kind = RawKind::End;
};

// The problem the lexer found, where (the token stream adds the file and its context).
struct LexError {
  int line = 0, col = 0;
  std::string message;
};

class SourceFile {
 public:
  // `name` names the file in messages; `folder` is where it lies.
  SourceFile(std::string name, std::filesystem::path folder, std::string text);

  const std::string& name() const { return name_; }
  const std::filesystem::path& folder() const { return folder_; }

  // The raw token at `index`, reading more of the file as needed; past the end of the file,
  // an End token. Throws LexError. The reference stays valid as more tokens are read.
  const RawToken& at(size_t index) {
    if (index < count_) return chunks_[index >> kChunkBits].get()[index & (kChunk - 1)];
    return readUpTo(index);
  }

  SourceLoc loc(const RawToken& t) const { return {name_, t.line, t.col}; }

 private:
  // Tokens are kept in chunks that never move, so references to them stay valid.
  static constexpr size_t kChunkBits = 10;
  static constexpr size_t kChunk = size_t{1} << kChunkBits;

  const RawToken& readUpTo(size_t index);
  void readNext();
  RawToken& push();
  void skipSpaceAndComments();
  void blockComment(int line, int col);
  void newLines(size_t from, size_t to);  // counts the line ends in text_[from, to)
  void readNumber(RawToken& t);
  void readWord(RawToken& t);
  void readString(RawToken& t);
  void readPunct(RawToken& t);
  int col() const { return static_cast<int>(pos_ - lineStart_) + 1; }

  std::string name_;
  std::filesystem::path folder_;
  std::string text_;
  // A chunk's memory is left untouched until its tokens are read (a small file touches only
  // the pages its tokens need); RawToken has no destructor to run.
  struct FreeChunk {
    void operator()(RawToken* p) const { ::operator delete(p); }
  };
  std::vector<std::unique_ptr<RawToken, FreeChunk>> chunks_;
  size_t count_ = 0;
  std::deque<std::string> unescaped_;  // string literals that held \" (views point here)
  size_t pos_ = 0;
  size_t lineStart_ = 0;  // where line_ begins in text_: a column is counted from it
  int line_ = 1;
  bool ended_ = false;
};

}  // namespace lucent::sdl
