/** @file error.c @brief Text for coll_err_t codes. */
#include "coll/common.h"

const char *coll_strerror(coll_err_t err)
{
    switch (err) {
    case COLL_OK: return "ok";
    case COLL_ERR_INVALID_ARG: return "invalid argument";
    case COLL_ERR_FULL: return "container full";
    case COLL_ERR_BUFFER_TOO_SMALL: return "buffer too small";
    case COLL_ERR_BAD_MAGIC: return "bad magic (not a coll blob)";
    case COLL_ERR_VERSION: return "unsupported format version (bake the level again with this release's collbake)";
    case COLL_ERR_TRUNCATED: return "truncated blob";
    case COLL_ERR_CORRUPT: return "corrupt blob";
    case COLL_ERR_ALIGNMENT: return "buffer not 8-byte aligned";
    case COLL_ERR_NOT_FOUND: return "not found";
    }
    return "unknown error";
}
