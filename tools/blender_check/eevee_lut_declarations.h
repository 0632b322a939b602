/* The declarations of EEVEE's two LTC arrays as Blender's eevee_lut.hh / eevee_lut.h make them,
 * so that ltc_export's definitions are compiled against each: LTC_EEVEE_FLOAT_ARRAYS,
 * LTC_EEVEE_VEC_BASE (with a VecBase of the shape of BLI_math_vector_types.hh's: one value per
 * component) or neither: the flat C arrays, which eevee_lut.h declares extern "C" for C++. */
#if defined(LTC_EEVEE_FLOAT_ARRAYS) || defined(LTC_EEVEE_VEC_BASE)
namespace blender {
template<typename T, int Size> struct VecBase;
template<typename T> struct VecBase<T, 2> {
  T x, y;
  VecBase(T x_, T y_) : x(x_), y(y_) {}
};
template<typename T> struct VecBase<T, 4> {
  T x, y, z, w;
  VecBase(T x_, T y_, T z_, T w_) : x(x_), y(y_), z(z_), w(w_) {}
};
}  // namespace blender
namespace blender::eevee::lut {
#  ifdef LTC_EEVEE_VEC_BASE
extern const VecBase<float, 4> ltc_mat_ggx[64][64];
extern const VecBase<float, 2> ltc_mag_ggx[64][64];
#  else
extern const float ltc_mat_ggx[64][64][4];
extern const float ltc_mag_ggx[64][64][2];
#  endif
}  // namespace blender::eevee::lut
#else
#  ifdef __cplusplus
extern "C" {
#  endif
extern const float ltc_mat_ggx[64 * 64 * 4];
extern const float ltc_mag_ggx[64 * 64 * 2];
#  ifdef __cplusplus
}
#  endif
#endif
