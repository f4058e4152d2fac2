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
#include <string>

namespace lucent::sdl {

enum class RawKind { Word, Number, String, Punct, End };

struct RawToken {
  RawKind kind = RawKind::End;
  // Word: the word. String: the characters between the quotes, `\"` read as `"` and every
  // other escape kept for later (a file name is read without them). Punct: the operator,
  // one of { } @ & ` \ | : , - $ = != ! ^ <= < ( [ % + ? >= > ) ] ; ' / * ~ # .
  std::string text;
  double number = 0;
  int keyword = -1;  // Word: its entry in keywords.h, or -1 for an identifier
  int line = 0, col = 0;
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
  const RawToken& at(size_t index);

  SourceLoc loc(const RawToken& t) const { return {name_, t.line, t.col}; }

 private:
  void readNext();
  int get();
  int peek(size_t ahead = 0) const;
  void skipSpaceAndComments();
  void blockComment(int line, int col);
  void readNumber(RawToken& t);
  void readWord(RawToken& t);
  void readString(RawToken& t);
  void readPunct(RawToken& t, int c);

  std::string name_;
  std::filesystem::path folder_;
  std::string text_;
  std::deque<RawToken> tokens_;
  size_t pos_ = 0;
  int line_ = 1, col_ = 1;
  bool ended_ = false;
};

}  // namespace lucent::sdl
