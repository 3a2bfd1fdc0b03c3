// fmt's compiled part (its formatting engine, Dragonbox, the locale hooks), built once for the
// module: the native build links Debian's libfmt, which emscripten cannot link, and header-only
// fmt would compile this part again in every unit. format.h declares these templates and the
// functions below; format-inl.h defines them, and the explicit instantiations here are the ones
// format.h's units call without instantiating them themselves.
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {

template auto dragonbox::to_decimal(float x) noexcept -> dragonbox::decimal_fp<float>;
template auto dragonbox::to_decimal(double x) noexcept -> dragonbox::decimal_fp<double>;

template locale_ref::locale_ref(const std::locale& loc);
template auto locale_ref::get<std::locale>() const -> std::locale;

template auto thousands_sep_impl(locale_ref) -> thousands_sep_result<char>;
template auto decimal_point_impl(locale_ref) -> char;
template void buffer<char>::append(const char*, const char*);

}  // namespace detail
FMT_END_NAMESPACE
