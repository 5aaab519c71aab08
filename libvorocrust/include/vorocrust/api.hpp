// vorocrust/api.hpp — what libvorocrust exports.
//
// The library is built with hidden symbols by default: only what its public headers mark
// VOROCRUST_API (functions, classes with out-of-line members, exceptions) is visible to programs
// linking it, so nothing of a stage's internals can become a dependency by accident. Types whose
// members are all inline need no mark.
#pragma once

#if defined(VOROCRUST_STATIC_DEFINE)
#define VOROCRUST_API
#else
#define VOROCRUST_API __attribute__((visibility("default")))
#endif
