#pragma once
// Whether this test program was built with AddressSanitizer (.ci/sanitize, RBSIM_SANITIZE). A
// long outcome run (ten seconds of a 200-box scene) takes minutes there and reaches no code a
// short run of the same scene does not: such tests run shorter or are skipped there, saying so,
// and keep their full length in the normal build.
namespace rbsim::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace rbsim::test
