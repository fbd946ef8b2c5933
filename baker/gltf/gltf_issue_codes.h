// The catalogue of glTF findings (internal to the baker): every kind of problem the load
// and validation stages report has one stable UPPER_SNAKE code, as KhronosGroup's
// glTF-Validator names its issues, with a default severity and a one-line meaning. The
// table is printed by `lfd-bake --list-issue-codes` and checked in as
// docs/baker/gltf-issues.md (a test compares the two).
//
// Severity rule (docs/baker/gltf-issues.md): a finding is reported with its code's
// default severity, except that an Error code found in a value the baker goes on without
// (an object nothing reads - samplers, cameras, skins, accessors and buffers no mesh or
// animation reads - or a value it replaces by a stated default) is reported as a Warning.
// Codes that only ever concern such values default to Warning.
#pragma once

#include <span>
#include <string>

namespace lfd::bake::gltf {

enum class IssueSeverity { Error, Warning };

// Whether the baker uses the value a finding concerns: kIgnored turns an Error code into a
// Warning (the severity rule above).
enum class Use { Read, Ignored };
inline constexpr Use kRead = Use::Read;
inline constexpr Use kIgnored = Use::Ignored;

// X(code, default severity, meaning). Grouped by the glTF object they concern; the order is
// the order of the generated table, and new codes go at the end of their group.
#define LFD_GLTF_ISSUE_CODES(X)                                                                                       \
    /* The container and the JSON text (glTF 2.0 sections 3.3, 4.4) */                                               \
    X(GLB_HEADER_INVALID, Error, "The GLB header is truncated, of another version, or declares a wrong length.")     \
    X(GLB_TRAILING_BYTES, Warning, "Bytes after the GLB's declared length; ignored.")                                \
    X(GLB_CHUNK_INVALID, Error, "A GLB chunk is truncated, misplaced, repeated, empty or misaligned.")               \
    X(GLB_UNKNOWN_CHUNK, Warning, "A GLB chunk of an unknown type; ignored.")                                        \
    X(JSON_BYTE_ORDER_MARK, Error, "The JSON starts with a UTF-8 byte-order mark.")                                  \
    X(INVALID_JSON, Error, "The JSON text does not parse.")                                                          \
    X(NUMBER_OUT_OF_RANGE, Error, "A JSON number beyond the range of double precision.")                             \
    X(TINYGLTF_WARNING, Warning, "A warning of the tinygltf parser, passed on.")                                     \
    /* Any property: the JSON schema */                                                                              \
    X(TYPE_MISMATCH, Error, "A value of the wrong JSON type (or not an integer where one is expected).")             \
    X(MISSING_REQUIRED_PROPERTY, Error, "A required property is absent.")                                            \
    X(VALUE_OUT_OF_RANGE, Error, "A number outside the range the schema allows.")                                    \
    X(VALUE_CLAMPED, Warning, "A factor outside its range; the baker clamps it.")                                    \
    X(ARRAY_LENGTH_MISMATCH, Error, "An array with the wrong number of elements.")                                   \
    X(EMPTY_ARRAY, Warning, "An array the schema requires to have elements is empty.")                               \
    X(VALUE_NOT_IN_LIST, Error, "A value that is not one of the enumeration's values.")                              \
    X(UNRESOLVED_REFERENCE, Error, "An index that names no element of the array it refers to.")                      \
    X(DUPLICATE_ELEMENT, Error, "An element listed twice where the schema requires unique items.")                   \
    X(PROPERTY_NOT_APPLICABLE, Warning, "A property that does not apply to the object's kind; ignored.")             \
    /* asset, extensionsUsed, extensionsRequired (sections 3.12, 4.3) */                                             \
    X(INVALID_VERSION, Error, "asset.version or asset.minVersion is not \"<major>.<minor>\".")                       \
    X(UNSUPPORTED_VERSION, Error, "A glTF version other than 2.0.")                                                  \
    X(REQUIRED_EXTENSION_NOT_USED, Error, "An extension in extensionsRequired is not in extensionsUsed.")            \
    /* scenes and nodes (sections 3.5) */                                                                            \
    X(SCENE_NON_ROOT_NODE, Error, "A scene lists a node that is the child of another.")                              \
    X(NODE_MULTIPLE_PARENTS, Error, "A node is the child of two nodes.")                                             \
    X(NODE_LOOP, Error, "A node is its own ancestor.")                                                               \
    X(NODE_MATRIX_TRS, Error, "A node has both a matrix and translation/rotation/scale.")                            \
    X(NODE_MATRIX_NON_TRS, Error, "A node matrix that is not decomposable into translation, rotation and scale.")    \
    X(NODE_ROTATION_NON_UNIT, Warning, "A node rotation that is not a unit quaternion; the baker normalises it.")     \
    X(WEIGHTS_COUNT_MISMATCH, Error, "Node or mesh weights not one per morph target.")                               \
    /* meshes and primitives (section 3.7) */                                                                        \
    X(UNKNOWN_ATTRIBUTE_SEMANTIC, Warning, "An attribute name glTF does not define and not starting with '_'.")       \
    X(MESH_PRIMITIVES_UNEQUAL_TARGETS_COUNT, Error, "Primitives of one mesh with different numbers of morph targets.") \
    X(MESH_PRIMITIVE_UNEQUAL_ACCESSOR_COUNT, Error, "Attributes (or morph targets) of a primitive with different counts.") \
    X(MORPH_TARGET_ATTRIBUTE_UNKNOWN, Error, "A morph target attribute the primitive itself does not have.")          \
    X(VERTEX_ATTRIBUTE_UNSIGNED_INT, Warning, "A vertex attribute of UNSIGNED_INT components; ignored.")             \
    X(SKINNING_ATTRIBUTES_UNPAIRED, Warning, "JOINTS_n and WEIGHTS_n attributes not in pairs.")                       \
    X(TEXCOORD_MISSING, Warning, "A material samples a TEXCOORD set the primitive lacks; uvs set to zero.")           \
    X(VERTEX_ATTRIBUTE_MISALIGNED, Error, "Vertex attribute data not aligned to 4 bytes.")                            \
    X(ACCESSOR_INDEX_PRIMITIVE_RESTART, Error, "Index data holding the primitive-restart value.")                     \
    X(ACCESSOR_INDEX_OOB, Error, "An index naming a vertex the primitive does not have.")                            \
    X(DRACO_ATTRIBUTE_UNKNOWN, Error, "A Draco attribute the primitive does not have.")                             \
    X(DRACO_MODE_UNSUPPORTED, Error, "A Draco-compressed primitive that is not a triangle list.")                   \
    X(DRACO_DECODE_FAILED, Error, "A Draco stream that does not decode, or not to what its accessors describe.")                                            \
    X(DRACO_ACCESSOR_SHARED, Error, "An accessor filled by two different Draco streams.")                            \
    /* accessors (section 3.6.2) */                                                                                  \
    X(ACCESSOR_WRONG_FORMAT, Error, "An accessor whose type or component type does not fit its use.")                \
    X(ACCESSOR_BOUNDS_MISSING, Error, "An accessor without the min and max its use requires.")                       \
    X(ACCESSOR_NORMALIZED_INVALID, Error, "normalized true for FLOAT or UNSIGNED_INT components.")                   \
    X(ACCESSOR_OFFSET_WITHOUT_BUFFER_VIEW, Error, "An accessor byteOffset without a bufferView.")                   \
    X(ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE, Error, "More sparse elements than the accessor has.")                      \
    X(ACCESSOR_SPARSE_INDEX_OOB, Error, "A sparse index not below the accessor's count.")                            \
    X(ACCESSOR_SPARSE_INDICES_NON_INCREASING, Error, "Sparse indices that do not increase strictly.")                \
    X(ACCESSOR_TOO_LONG, Error, "An accessor's elements do not fit its buffer view.")                                \
    X(ACCESSOR_ELEMENT_LONGER_THAN_STRIDE, Error, "An accessor element longer than its buffer view's byteStride.")  \
    X(ACCESSOR_OFFSET_ALIGNMENT, Error, "An accessor byteOffset not a multiple of its component size.")              \
    X(ACCESSOR_TOTAL_OFFSET_ALIGNMENT, Error, "An accessor's start in its buffer not a multiple of its component size.") \
    X(ACCESSOR_NON_FINITE, Error, "An accessor value that is NaN or infinite.")                                      \
    X(ACCESSOR_NON_UNIT, Warning, "A normal or tangent that is not unit length; the baker renormalises it.")         \
    X(ACCESSOR_INVALID_SIGN, Warning, "A tangent w other than 1 or -1; its sign is used.")                           \
    X(ACCESSOR_READ_FAILED, Error, "An accessor whose data cannot be read.")                                         \
    /* buffer views and buffers (section 3.6.1) */                                                                   \
    X(BUFFER_VIEW_INVALID_BYTE_STRIDE, Error, "A byteStride that is not a multiple of 4.")                           \
    X(BUFFER_VIEW_STRIDE_ON_INDEX_DATA, Error, "A byteStride on a buffer view of index data.")                       \
    X(BUFFER_VIEW_STRIDE_EXCEEDS_LENGTH, Error, "A byteStride larger than the buffer view.")                         \
    X(BUFFER_VIEW_TOO_LONG, Error, "A buffer view that does not fit its buffer.")                                   \
    X(BUFFER_VIEW_TARGET_MISMATCH, Error, "A buffer view used for vertex and index data, or against its target.")    \
    X(BUFFER_VIEW_SHARED_WITHOUT_STRIDE, Error, "Several vertex attributes in a buffer view without a byteStride.")   \
    X(MESHOPT_BOTH_EXTENSIONS, Error, "A buffer view with both EXT_ and KHR_meshopt_compression.")                   \
    X(MESHOPT_INVALID, Error, "A meshopt extension object that breaks the extension's validity rules.")              \
    X(MESHOPT_DECODED_TOO_LONG, Error, "Meshopt data that decodes to more bytes than its buffer holds.")             \
    X(MESHOPT_DECODE_FAILED, Error, "A meshopt stream that does not decode (corrupt, truncated, unsupported codec).")                                        \
    X(COMPRESSED_DATA_OUT_OF_BOUNDS, Error, "Compressed data that does not fit its buffer.")                         \
    X(URI_NOT_FETCHED, Error, "A remote URI; the baker does not fetch it.")                                          \
    X(DATA_URI_MALFORMED, Error, "A data URI that does not decode.")                                                 \
    X(DATA_URI_EMPTY, Error, "A data URI without data.")                                                             \
    X(DATA_URI_MEDIA_TYPE_INVALID, Error, "A data URI of a media type the object cannot hold.")                      \
    X(RESOURCE_NOT_FOUND, Error, "A buffer file that does not exist.")                                               \
    X(BUFFER_BYTE_LENGTH_MISMATCH, Error, "A buffer byteLength the data does not match.")                            \
    X(GLB_BIN_CHUNK_MISSING, Error, "A GLB buffer without uri in a GLB without a BIN chunk.")                        \
    X(GLB_BIN_CHUNK_UNUSED_BYTES, Warning, "More than 3 bytes of the BIN chunk past the buffer's byteLength.")       \
    /* materials, textures, samplers, images (sections 3.8, 3.9) */                                                  \
    X(IMAGE_BUFFER_VIEW_WITH_BYTESTRIDE, Error, "An image in a buffer view with a byteStride.")                      \
    X(IMAGE_SOURCE_CONFLICT, Error, "An image with both uri and bufferView.")                                        \
    X(IMAGE_SOURCE_MISSING, Error, "An image with neither uri nor bufferView.")                                      \
    X(IMAGE_MIME_TYPE_UNKNOWN, Warning, "An image mimeType the file cannot hold; decoded by content.")               \
    X(IMAGE_MIME_TYPE_MISSING, Warning, "An image in a buffer view without mimeType; decoded by content.")           \
    X(IMAGE_MIME_TYPE_MISMATCH, Warning, "An image mimeType that differs from its data URI's; decoded by content.")  \
    /* animations (section 3.11) */                                                                                  \
    X(ANIMATION_DUPLICATE_TARGETS, Error, "Two channels of one animation with the same target.")                     \
    X(ANIMATION_CHANNEL_TARGET_NODE_MATRIX, Error, "A channel animating translation/rotation/scale of a node with a matrix.") \
    X(ANIMATION_CHANNEL_TARGET_NODE_WEIGHTS_NO_MORPHS, Error, "Weights animated on a node without morph targets.")  \
    X(ANIMATION_SAMPLER_ACCESSOR_WITH_BYTESTRIDE, Error, "Animation data in a buffer view with a byteStride.")        \
    X(ANIMATION_KEY_TIME_INVALID, Error, "A key time that is negative or not finite.")                               \
    X(ANIMATION_KEY_TIMES_NOT_INCREASING, Error, "Key times that do not increase strictly.")                         \
    X(ANIMATION_CUBICSPLINE_TOO_FEW_KEYS, Error, "A CUBICSPLINE sampler with fewer than 2 keys.")                     \
    X(ANIMATION_SAMPLER_OUTPUT_COUNT_MISMATCH, Error, "Animation output not as many values as its keys need.")       \
    /* lights, cameras, skins (KHR_lights_punctual; sections 3.10, 3.7.3) */                                         \
    X(LIGHT_RANGE_NOT_POSITIVE, Warning, "A light range not above zero; treated as unlimited.")                      \
    X(SPOT_CONE_INVALID, Error, "A spot light whose inner cone angle is not below the outer.")                       \
    X(CAMERA_ZFAR_NOT_GREATER, Warning, "A camera zfar not greater than znear; camera ignored.")                     \
    X(SKIN_TOO_FEW_MATRICES, Warning, "Fewer inverse bind matrices than joints.")                                    \
    X(SKIN_IBM_ACCESSOR_WITH_BYTESTRIDE, Warning, "Inverse bind matrices in a buffer view with a byteStride.")       \
    X(SKIN_NO_COMMON_ROOT, Warning, "Skin joints without a common root.")                                            \
    X(SKIN_SKELETON_INVALID, Warning, "A skin skeleton that is not an ancestor of every joint.")

enum class IssueCode {
#define LFD_GLTF_ISSUE_ENUM(code, severity, meaning) code,
    LFD_GLTF_ISSUE_CODES(LFD_GLTF_ISSUE_ENUM)
#undef LFD_GLTF_ISSUE_ENUM
};

struct IssueCodeInfo {
    IssueCode code;
    const char* name;          // "TYPE_MISMATCH"
    IssueSeverity severity;    // default severity (see the rule above)
    const char* description;   // one line
};

// Every code, in catalogue order.
std::span<const IssueCodeInfo> issueCodes();
const IssueCodeInfo& issueCodeInfo(IssueCode code);

// The catalogue as the Markdown table of docs/baker/gltf-issues.md.
std::string issueCodeTable();

} // namespace lfd::bake::gltf
