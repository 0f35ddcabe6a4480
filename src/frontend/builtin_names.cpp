#include "frontend/builtin_names.hpp"

namespace doublet::frontend {
using namespace glslang;

const char* binary_operator_spelling(TOperator op) {
  switch (op) {
    case EOpAdd: return "+";
    case EOpSub: return "-";
    case EOpMul:
    case EOpVectorTimesScalar:
    case EOpVectorTimesMatrix:
    case EOpMatrixTimesVector:
    case EOpMatrixTimesScalar:
    case EOpMatrixTimesMatrix: return "*";
    case EOpDiv: return "/";
    case EOpMod: return "%";
    case EOpRightShift: return ">>";
    case EOpLeftShift: return "<<";
    case EOpAnd: return "&";
    case EOpInclusiveOr: return "|";
    case EOpExclusiveOr: return "^";
    case EOpEqual: return "==";
    case EOpNotEqual: return "!=";
    case EOpLessThan: return "<";
    case EOpGreaterThan: return ">";
    case EOpLessThanEqual: return "<=";
    case EOpGreaterThanEqual: return ">=";
    case EOpComma: return ",";
    case EOpLogicalOr: return "||";
    case EOpLogicalXor: return "^^";
    case EOpLogicalAnd: return "&&";
    case EOpAssign: return "=";
    case EOpAddAssign: return "+=";
    case EOpSubAssign: return "-=";
    case EOpMulAssign:
    case EOpVectorTimesMatrixAssign:
    case EOpVectorTimesScalarAssign:
    case EOpMatrixTimesScalarAssign:
    case EOpMatrixTimesMatrixAssign: return "*=";
    case EOpDivAssign: return "/=";
    case EOpModAssign: return "%=";
    case EOpAndAssign: return "&=";
    case EOpInclusiveOrAssign: return "|=";
    case EOpExclusiveOrAssign: return "^=";
    case EOpLeftShiftAssign: return "<<=";
    case EOpRightShiftAssign: return ">>=";
    default: return nullptr;
  }
}

const char* unary_operator_spelling(TOperator op) {
  switch (op) {
    case EOpNegative: return "-";
    case EOpLogicalNot: return "!";
    case EOpBitwiseNot: return "~";
    case EOpPreIncrement: return "++x";
    case EOpPreDecrement: return "--x";
    case EOpPostIncrement: return "x++";
    case EOpPostDecrement: return "x--";
    default: return nullptr;
  }
}

bool is_conversion(TOperator op) {
  return op >= EOpConvInt8ToBool && op <= EOpConvDoubleToFloat;
}

const char* builtin_function_name(TOperator op, int args) {
  switch (op) {
    case EOpVectorLogicalNot: return "not";
    case EOpRadians: return "radians";
    case EOpDegrees: return "degrees";
    case EOpSin: return "sin";
    case EOpCos: return "cos";
    case EOpTan: return "tan";
    case EOpAsin: return "asin";
    case EOpAcos: return "acos";
    case EOpAtan: return "atan";
    case EOpSinh: return "sinh";
    case EOpCosh: return "cosh";
    case EOpTanh: return "tanh";
    case EOpAsinh: return "asinh";
    case EOpAcosh: return "acosh";
    case EOpAtanh: return "atanh";
    case EOpPow: return "pow";
    case EOpExp: return "exp";
    case EOpLog: return "log";
    case EOpExp2: return "exp2";
    case EOpLog2: return "log2";
    case EOpSqrt: return "sqrt";
    case EOpInverseSqrt: return "inversesqrt";
    case EOpAbs: return "abs";
    case EOpSign: return "sign";
    case EOpFloor: return "floor";
    case EOpTrunc: return "trunc";
    case EOpRound: return "round";
    case EOpRoundEven: return "roundEven";
    case EOpCeil: return "ceil";
    case EOpFract: return "fract";
    case EOpModf: return "modf";
    case EOpMod: return "mod";
    case EOpMin: return "min";
    case EOpMax: return "max";
    case EOpClamp: return "clamp";
    case EOpMix: return "mix";
    case EOpStep: return "step";
    case EOpSmoothStep: return "smoothstep";
    case EOpIsNan: return "isnan";
    case EOpIsInf: return "isinf";
    case EOpFma: return "fma";
    case EOpFrexp: return "frexp";
    case EOpLdexp: return "ldexp";
    case EOpFloatBitsToInt: return "floatBitsToInt";
    case EOpFloatBitsToUint: return "floatBitsToUint";
    case EOpIntBitsToFloat: return "intBitsToFloat";
    case EOpUintBitsToFloat: return "uintBitsToFloat";
    case EOpPackSnorm2x16: return "packSnorm2x16";
    case EOpUnpackSnorm2x16: return "unpackSnorm2x16";
    case EOpPackUnorm2x16: return "packUnorm2x16";
    case EOpUnpackUnorm2x16: return "unpackUnorm2x16";
    case EOpPackSnorm4x8: return "packSnorm4x8";
    case EOpUnpackSnorm4x8: return "unpackSnorm4x8";
    case EOpPackUnorm4x8: return "packUnorm4x8";
    case EOpUnpackUnorm4x8: return "unpackUnorm4x8";
    case EOpPackHalf2x16: return "packHalf2x16";
    case EOpUnpackHalf2x16: return "unpackHalf2x16";
    case EOpPackDouble2x32: return "packDouble2x32";
    case EOpUnpackDouble2x32: return "unpackDouble2x32";
    case EOpPackInt2x32: return "packInt2x32";
    case EOpUnpackInt2x32: return "unpackInt2x32";
    case EOpPackUint2x32: return "packUint2x32";
    case EOpUnpackUint2x32: return "unpackUint2x32";
    case EOpDoubleBitsToInt64: return "doubleBitsToInt64";
    case EOpDoubleBitsToUint64: return "doubleBitsToUint64";
    case EOpInt64BitsToDouble: return "int64BitsToDouble";
    case EOpUint64BitsToDouble: return "uint64BitsToDouble";
    case EOpLength: return "length";
    case EOpDistance: return "distance";
    case EOpDot: return "dot";
    case EOpCross: return "cross";
    case EOpNormalize: return "normalize";
    case EOpFaceForward: return "faceforward";
    case EOpReflect: return "reflect";
    case EOpRefract: return "refract";
    case EOpDPdx: return "dFdx";
    case EOpDPdy: return "dFdy";
    case EOpFwidth: return "fwidth";
    case EOpMul: return args == 2 ? "matrixCompMult" : nullptr;
    case EOpOuterProduct: return "outerProduct";
    case EOpDeterminant: return "determinant";
    case EOpMatrixInverse: return "inverse";
    case EOpTranspose: return "transpose";
    case EOpLessThan: return "lessThan";
    case EOpGreaterThan: return "greaterThan";
    case EOpLessThanEqual: return "lessThanEqual";
    case EOpGreaterThanEqual: return "greaterThanEqual";
    case EOpVectorEqual: return "equal";
    case EOpVectorNotEqual: return "notEqual";
    case EOpAny: return "any";
    case EOpAll: return "all";
    case EOpBarrier: return "barrier";
    case EOpEmitVertex: return "EmitVertex";
    case EOpEndPrimitive: return "EndPrimitive";
    case EOpEmitStreamVertex: return "EmitStreamVertex";
    case EOpEndStreamPrimitive: return "EndStreamPrimitive";
    case EOpMemoryBarrier: return "memoryBarrier";
    case EOpMemoryBarrierBuffer: return "memoryBarrierBuffer";
    case EOpMemoryBarrierShared: return "memoryBarrierShared";
    case EOpMemoryBarrierImage: return "memoryBarrierImage";
    case EOpGroupMemoryBarrier: return "groupMemoryBarrier";
    case EOpBitfieldExtract: return "bitfieldExtract";
    case EOpBitfieldInsert: return "bitfieldInsert";
    case EOpBitFieldReverse: return "bitfieldReverse";
    case EOpBitCount: return "bitCount";
    case EOpFindLSB: return "findLSB";
    case EOpFindMSB: return "findMSB";
    case EOpUMulExtended: return "umulExtended";
    case EOpIMulExtended: return "imulExtended";
    case EOpAddCarry: return "uaddCarry";
    case EOpSubBorrow: return "usubBorrow";
    case EOpTexture: return "texture";
    case EOpTextureProj: return "textureProj";
    case EOpTextureLod: return "textureLod";
    case EOpTextureOffset: return "textureOffset";
    case EOpTextureFetch: return "texelFetch";
    case EOpTextureFetchOffset: return "texelFetchOffset";
    case EOpTextureProjOffset: return "textureProjOffset";
    case EOpTextureLodOffset: return "textureLodOffset";
    case EOpTextureProjLod: return "textureProjLod";
    case EOpTextureGrad: return "textureGrad";
    case EOpTextureGradOffset: return "textureGradOffset";
    case EOpTextureProjGrad: return "textureProjGrad";
    case EOpTextureGather: return "textureGather";
    case EOpTextureGatherOffset: return "textureGatherOffset";
    case EOpTextureQuerySize: return "textureSize";
    case EOpTextureQueryLevels: return "textureQueryLevels";
    case EOpImageQuerySize: return "imageSize";
    case EOpImageQuerySamples: return "imageSamples";
    case EOpImageLoad: return "imageLoad";
    case EOpImageStore: return "imageStore";
    case EOpImageAtomicAdd: return "imageAtomicAdd";
    case EOpImageAtomicMin: return "imageAtomicMin";
    case EOpImageAtomicMax: return "imageAtomicMax";
    case EOpImageAtomicAnd: return "imageAtomicAnd";
    case EOpImageAtomicOr: return "imageAtomicOr";
    case EOpImageAtomicXor: return "imageAtomicXor";
    case EOpImageAtomicExchange: return "imageAtomicExchange";
    case EOpImageAtomicCompSwap: return "imageAtomicCompSwap";
    case EOpTextureQueryLod: return "textureQueryLod";
    case EOpTextureQuerySamples: return "textureSamples";
    case EOpAtomicAdd: return "atomicAdd";
    case EOpAtomicMin: return "atomicMin";
    case EOpAtomicMax: return "atomicMax";
    case EOpAtomicAnd: return "atomicAnd";
    case EOpAtomicOr: return "atomicOr";
    case EOpAtomicXor: return "atomicXor";
    case EOpAtomicExchange: return "atomicExchange";
    case EOpAtomicCompSwap: return "atomicCompSwap";
    case EOpAtomicCounterIncrement: return "atomicCounterIncrement";
    case EOpAtomicCounterDecrement: return "atomicCounterDecrement";
    case EOpAtomicCounter: return "atomicCounter";
    case EOpAtomicCounterAdd: return "atomicCounterAdd";
    case EOpAtomicCounterSubtract: return "atomicCounterSubtract";
    case EOpAtomicCounterMin: return "atomicCounterMin";
    case EOpAtomicCounterMax: return "atomicCounterMax";
    case EOpAtomicCounterAnd: return "atomicCounterAnd";
    case EOpAtomicCounterOr: return "atomicCounterOr";
    case EOpAtomicCounterXor: return "atomicCounterXor";
    case EOpAtomicCounterExchange: return "atomicCounterExchange";
    case EOpAtomicCounterCompSwap: return "atomicCounterCompSwap";
    // GL_KHR_memory_scope_semantics; the rest of the texture functions.
    case EOpAtomicLoad: return "atomicLoad";
    case EOpAtomicStore: return "atomicStore";
    case EOpTextureProjGradOffset: return "textureProjGradOffset";
    case EOpTextureProjLodOffset: return "textureProjLodOffset";
    // GL_KHR_shader_subgroup_* (the NV partitioned forms are not GLSL's).
    case EOpSubgroupBarrier: return "subgroupBarrier";
    case EOpSubgroupMemoryBarrier: return "subgroupMemoryBarrier";
    case EOpSubgroupMemoryBarrierBuffer: return "subgroupMemoryBarrierBuffer";
    case EOpSubgroupMemoryBarrierImage: return "subgroupMemoryBarrierImage";
    case EOpSubgroupMemoryBarrierShared: return "subgroupMemoryBarrierShared";
    case EOpSubgroupElect: return "subgroupElect";
    case EOpSubgroupAll: return "subgroupAll";
    case EOpSubgroupAny: return "subgroupAny";
    case EOpSubgroupAllEqual: return "subgroupAllEqual";
    case EOpSubgroupBroadcast: return "subgroupBroadcast";
    case EOpSubgroupBroadcastFirst: return "subgroupBroadcastFirst";
    case EOpSubgroupBallot: return "subgroupBallot";
    case EOpSubgroupInverseBallot: return "subgroupInverseBallot";
    case EOpSubgroupBallotBitExtract: return "subgroupBallotBitExtract";
    case EOpSubgroupBallotBitCount: return "subgroupBallotBitCount";
    case EOpSubgroupBallotInclusiveBitCount: return "subgroupBallotInclusiveBitCount";
    case EOpSubgroupBallotExclusiveBitCount: return "subgroupBallotExclusiveBitCount";
    case EOpSubgroupBallotFindLSB: return "subgroupBallotFindLSB";
    case EOpSubgroupBallotFindMSB: return "subgroupBallotFindMSB";
    case EOpSubgroupShuffle: return "subgroupShuffle";
    case EOpSubgroupShuffleXor: return "subgroupShuffleXor";
    case EOpSubgroupShuffleUp: return "subgroupShuffleUp";
    case EOpSubgroupShuffleDown: return "subgroupShuffleDown";
    case EOpSubgroupAdd: return "subgroupAdd";
    case EOpSubgroupInclusiveAdd: return "subgroupInclusiveAdd";
    case EOpSubgroupExclusiveAdd: return "subgroupExclusiveAdd";
    case EOpSubgroupClusteredAdd: return "subgroupClusteredAdd";
    case EOpSubgroupMul: return "subgroupMul";
    case EOpSubgroupInclusiveMul: return "subgroupInclusiveMul";
    case EOpSubgroupExclusiveMul: return "subgroupExclusiveMul";
    case EOpSubgroupClusteredMul: return "subgroupClusteredMul";
    case EOpSubgroupMin: return "subgroupMin";
    case EOpSubgroupInclusiveMin: return "subgroupInclusiveMin";
    case EOpSubgroupExclusiveMin: return "subgroupExclusiveMin";
    case EOpSubgroupClusteredMin: return "subgroupClusteredMin";
    case EOpSubgroupMax: return "subgroupMax";
    case EOpSubgroupInclusiveMax: return "subgroupInclusiveMax";
    case EOpSubgroupExclusiveMax: return "subgroupExclusiveMax";
    case EOpSubgroupClusteredMax: return "subgroupClusteredMax";
    case EOpSubgroupAnd: return "subgroupAnd";
    case EOpSubgroupInclusiveAnd: return "subgroupInclusiveAnd";
    case EOpSubgroupExclusiveAnd: return "subgroupExclusiveAnd";
    case EOpSubgroupClusteredAnd: return "subgroupClusteredAnd";
    case EOpSubgroupOr: return "subgroupOr";
    case EOpSubgroupInclusiveOr: return "subgroupInclusiveOr";
    case EOpSubgroupExclusiveOr: return "subgroupExclusiveOr";
    case EOpSubgroupClusteredOr: return "subgroupClusteredOr";
    case EOpSubgroupXor: return "subgroupXor";
    case EOpSubgroupInclusiveXor: return "subgroupInclusiveXor";
    case EOpSubgroupExclusiveXor: return "subgroupExclusiveXor";
    case EOpSubgroupClusteredXor: return "subgroupClusteredXor";
    case EOpSubgroupQuadBroadcast: return "subgroupQuadBroadcast";
    case EOpSubgroupQuadSwapHorizontal: return "subgroupQuadSwapHorizontal";
    case EOpSubgroupQuadSwapVertical: return "subgroupQuadSwapVertical";
    case EOpSubgroupQuadSwapDiagonal: return "subgroupQuadSwapDiagonal";
    default: return nullptr;
  }
}

}  // namespace doublet::frontend
