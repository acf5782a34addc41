/* The runtime side of the OpenXR loader's negotiation (loader interface
 * version 1, the structs' version 1), written from the OpenXR loader
 * specification: Debian's libopenxr-dev 1.0.20 ships no loader_interfaces.h.
 * Only the mock runtime and the tests that reach it use this. */
#ifndef PROX_TESTS_OPENXR_LOADER_NEGOTIATION_H
#define PROX_TESTS_OPENXR_LOADER_NEGOTIATION_H

#include <openxr/openxr.h>

#include <stddef.h>
#include <stdint.h>

#define PROX_MOCK_XR_LOADER_INTERFACE_VERSION 1
#define PROX_MOCK_XR_LOADER_INFO_STRUCT_VERSION 1
#define PROX_MOCK_XR_RUNTIME_INFO_STRUCT_VERSION 1

typedef enum ProxMockXrLoaderInterfaceStructs {
  PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_UNINITIALIZED = 0,
  PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1,
  PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST = 2,
  PROX_MOCK_XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3
} ProxMockXrLoaderInterfaceStructs;

typedef struct ProxMockXrNegotiateLoaderInfo {
  ProxMockXrLoaderInterfaceStructs structType;
  uint32_t structVersion;
  size_t structSize;
  uint32_t minInterfaceVersion;
  uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
} ProxMockXrNegotiateLoaderInfo;

typedef struct ProxMockXrNegotiateRuntimeRequest {
  ProxMockXrLoaderInterfaceStructs structType;
  uint32_t structVersion;
  size_t structSize;
  uint32_t runtimeInterfaceVersion;
  XrVersion runtimeApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
} ProxMockXrNegotiateRuntimeRequest;

typedef XrResult (*ProxMockXrNegotiateFn)(const ProxMockXrNegotiateLoaderInfo* loaderInfo,
                                          ProxMockXrNegotiateRuntimeRequest* runtimeRequest);

#endif
