#pragma once
// The browser edition's page, for the parts of it that live outside the framework (the grader's self-check in the
// page, grader/src/app/page_self_check.cpp). Only in builds made with Emscripten (cmake/web.cmake).
#include <string>

namespace gsv {

struct Session;

// The session web mode handed to the page; throws gsv::Error when the lab has not started.
Session& web_session();

}  // namespace gsv
