#include "file_access.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace fs = std::filesystem;

namespace lucent {

fs::path canonicalPath(const fs::path& p) {
  // An existing path: realpath(3) resolves it in one call (what weakly_canonical does, with
  // far less work per component); the rest of the path is then as the code below makes it.
  if (!p.empty()) {
    if (char* real = ::realpath(p.c_str(), nullptr)) {
      fs::path c(real);
      std::free(real);
      return c;
    }
  }
  std::error_code ec;
  fs::path abs = fs::absolute(p, ec);
  if (ec) abs = p;
  fs::path c = fs::weakly_canonical(abs, ec);
  if (ec) c = abs.lexically_normal();
  if (!c.has_filename() && c.has_parent_path() && c != c.root_path()) c = c.parent_path();
  return c;
}

FileAccess::FileAccess(const fs::path& sceneFolder, const std::vector<std::string>& allowPaths,
                       const FileReplay* replay, GrantObserver onGrant)
    : replay_(replay), onGrant_(std::move(onGrant)) {
  roots_.push_back(canonicalPath(sceneFolder.empty() ? fs::path(".") : sceneFolder));
  for (const std::string& p : allowPaths) roots_.push_back(canonicalPath(p));
}

bool FileAccess::allowed(const fs::path& canonical) const {
  for (const fs::path& root : roots_) {
    // Component-wise prefix test: /a/bc is not inside /a/b.
    auto r = root.begin(), p = canonical.begin();
    for (; r != root.end() && p != canonical.end(); ++r, ++p)
      if (*r != *p) break;
    if (r == root.end()) return true;
  }
  return false;
}

FileAccess::Resolved FileAccess::resolve(const std::string& written,
                                         const fs::path& baseFolder) const {
  Resolved out;
  if (written.empty()) {
    out.error = "the path is empty";
    return out;
  }
  if (replay_) return replayed(written, baseFolder);
  fs::path p(written);
  if (p.is_relative()) p = baseFolder / p;
  fs::path c = canonicalPath(p);
  if (!allowed(c)) {
    std::string folders;
    for (size_t i = 0; i < roots_.size(); ++i) folders += (i ? ", " : "") + roots_[i].string();
    out.error = "'" + written + "' leads to '" + c.string() +
                "', outside the folders this scene may read (" + folders +
                "); use --allow-path to permit another folder";
    return out;
  }
  std::error_code ec;
  if (!fs::exists(c, ec)) {
    out.error = "file '" + written + "' not found (looked for '" + c.string() + "')";
    return out;
  }
  if (!fs::is_regular_file(c, ec)) {
    out.error = "'" + written + "' is not a regular file";
    return out;
  }
  out.path = c;
  grant(written, canonicalPath(baseFolder), c);
  return out;
}

void FileAccess::grant(const std::string& written, const fs::path& base, const fs::path& c) const {
  FileGrant g{written, base, c};
  {
    std::lock_guard<std::mutex> lock(grantedMutex_);
    if (std::find(granted_.begin(), granted_.end(), c) == granted_.end()) granted_.push_back(c);
    if (std::find(grants_.begin(), grants_.end(), g) != grants_.end()) return;
    grants_.push_back(g);
  }
  if (onGrant_) onGrant_(g);  // outside the lock: it may take a while (send the file)
}

// `p` with the leading components `root` taken off, as an absolute path; empty if `p`
// is not under `root`.
static fs::path underRoot(const fs::path& p, const fs::path& root) {
  auto r = root.begin(), q = p.begin();
  for (; r != root.end(); ++r, ++q)
    if (q == p.end() || *r != *q) return {};
  fs::path rest = "/";
  for (; q != p.end(); ++q) rest /= *q;
  return rest;
}

FileAccess::Resolved FileAccess::replayed(const std::string& written,
                                          const fs::path& baseFolder) const {
  Resolved out;
  const fs::path base = underRoot(canonicalPath(baseFolder), replay_->root);
  do {
    for (const FileGrant& g : replay_->grants)
      if (g.written == written && g.base == base) {
        out.path = replay_->root / g.canonical.relative_path();
        grant(written, canonicalPath(baseFolder), out.path);
        return out;
      }
  } while (replay_->more && replay_->more());
  out.error = "'" + written + "' (from '" + base.string() +
              "') is not among the files the first process sent";
  return out;
}

std::vector<fs::path> FileAccess::granted() const {
  std::lock_guard<std::mutex> lock(grantedMutex_);
  return granted_;
}

std::vector<FileGrant> FileAccess::grants() const {
  std::lock_guard<std::mutex> lock(grantedMutex_);
  return grants_;
}

}  // namespace lucent
