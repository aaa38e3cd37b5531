#include "vtkSurfaceMapsExecutive.h"

#include "vtkSurfaceMapsErrorGuard.h"

#include "vtkAbstractPolyDataReader.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataObject.h"
#include "vtkDataReader.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkInformationExecutivePortKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkXMLReader.h"

#include "vtkSurfaceMeshReader.h"

vtkStandardNewMacro(vtkSurfaceMapsExecutive);

namespace
{

// The file a reader reads, where the reader's class tells; nullptr otherwise.
const char* fileNameOf(vtkAlgorithm* algorithm)
{
  if (auto* xml = vtkXMLReader::SafeDownCast(algorithm))
  {
    return xml->GetFileName();
  }
  if (auto* legacy = vtkDataReader::SafeDownCast(algorithm))
  {
    return legacy->GetFileName();
  }
  if (auto* geometry = vtkAbstractPolyDataReader::SafeDownCast(algorithm))
  {
    return geometry->GetFileName();
  }
  if (auto* surface = vtkSurfaceMeshReader::SafeDownCast(algorithm))
  {
    return surface->GetFileName();
  }
  return nullptr;
}

// What `algorithm` says about its failure: "" when it says nothing.
std::string failureOf(vtkAlgorithm* algorithm)
{
  const std::string message = vtkSurfaceMapsErrorGuard::LastErrorMessage(algorithm);
  const unsigned long code = algorithm->GetErrorCode();
  if (message.empty() && code == vtkErrorCode::NoError)
  {
    return std::string();
  }
  std::string text = std::string(algorithm->GetClassName()) + " failed";
  const char* file = fileNameOf(algorithm);
  if (file && *file && message.find(file) == std::string::npos)
  {
    text += std::string(" (file ") + file + ")";
  }
  if (!message.empty())
  {
    return text + ": " + message;
  }
  const char* name = vtkErrorCode::GetStringFromErrorCode(code);
  return text + ": error code " + std::to_string(code) + (name ? std::string(" ") + name : "");
}

// The failure furthest upstream of `algorithm` (itself included) that says
// what went wrong; "" when none does.
std::string deepestFailure(vtkAlgorithm* algorithm)
{
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int j = 0; j < algorithm->GetNumberOfInputConnections(port); ++j)
    {
      vtkAlgorithmOutput* input = algorithm->GetInputConnection(port, j);
      if (vtkAlgorithm* producer = input ? input->GetProducer() : nullptr)
      {
        const std::string upstream = deepestFailure(producer);
        if (!upstream.empty())
        {
          return upstream;
        }
      }
    }
  }
  return failureOf(algorithm);
}

// Why input `connection` of port `port` of `algorithm` was not produced:
// "input 1 was not produced: vtkXMLPolyDataReader failed (file a.vtp)"
// ("input port 1 was not produced: ..." for other ports of several),
// naming the algorithm furthest upstream that says what went wrong (an error
// message of the module's, a non-zero error code), else the input's producer.
std::string upstreamFailure(vtkAlgorithm* algorithm, int port, int connection)
{
  // A repeatable first port counts its connections as inputs (the map's
  // "input 1"; its optional port 1, an existing map, is named by port).
  vtkInformation* first = algorithm->GetInputPortInformation(0);
  const bool counted = algorithm->GetNumberOfInputPorts() == 1 ||
    (port == 0 && first && first->Get(vtkAlgorithm::INPUT_IS_REPEATABLE()) == 1);
  const std::string input =
    (counted ? "input " + std::to_string(connection)
             : "input port " + std::to_string(port) +
          (connection > 0 ? " connection " + std::to_string(connection) : "")) +
    " was not produced: ";
  vtkAlgorithmOutput* output = algorithm->GetInputConnection(port, connection);
  vtkAlgorithm* producer = output ? output->GetProducer() : nullptr;
  if (!producer)
  {
    return input + "it has no producer";
  }
  const std::string failure = deepestFailure(producer);
  if (!failure.empty())
  {
    return input + failure;
  }
  const char* file = fileNameOf(producer);
  return input + producer->GetClassName() + " failed" +
    (file && *file ? std::string(" (file ") + file + ")" : std::string());
}

} // namespace

int vtkSurfaceMapsExecutive::ForwardUpstream(vtkInformation* request)
{
  // vtkExecutive::ForwardUpstream, remembering which input failed.
  if (this->SharedInputInformation)
  {
    return 1;
  }
  if (!this->Algorithm->ModifyRequest(request, BeforeForward))
  {
    return 0;
  }
  int failedPort = -1, failedConnection = -1;
  for (int i = 0; i < this->GetNumberOfInputPorts(); ++i)
  {
    vtkInformationVector* inVector = this->GetInputInformation()[i];
    for (int j = 0; j < this->Algorithm->GetNumberOfInputConnections(i); ++j)
    {
      vtkExecutive* producer;
      int producerPort;
      vtkExecutive::PRODUCER()->Get(inVector->GetInformationObject(j), producer, producerPort);
      if (producer)
      {
        const int port = request->Get(FROM_OUTPUT_PORT());
        request->Set(FROM_OUTPUT_PORT(), producerPort);
        if (!producer->ProcessRequest(
              request, producer->GetInputInformation(), producer->GetOutputInformation()) &&
          failedPort < 0)
        {
          failedPort = i;
          failedConnection = j;
        }
        request->Set(FROM_OUTPUT_PORT(), port);
      }
    }
  }
  if (!this->Algorithm->ModifyRequest(request, AfterForward))
  {
    return 0;
  }
  if (failedPort < 0)
  {
    return 1;
  }
  for (int i = 0; i < this->GetNumberOfOutputPorts(); ++i)
  {
    if (vtkDataObject* output = this->GetOutputData(i))
    {
      output->Initialize();
    }
  }
  return vtkSurfaceMapsErrorGuard::Fail(this->Algorithm,
    vtkSurfaceMapsErrorGuard::InvalidInputError,
    upstreamFailure(this->Algorithm, failedPort, failedConnection));
}

int vtkSurfaceMapsExecutive::CallAlgorithm(vtkInformation* request,
  int direction,
  vtkInformationVector** inInfo,
  vtkInformationVector* outInfo)
{
  // vtkExecutive::CallAlgorithm, without the dump of the request after a
  // failure the algorithm reported itself.
  this->CopyDefaultInformation(request, direction, inInfo, outInfo);
  const int reports = vtkSurfaceMapsErrorGuard::NumberOfReports(this->Algorithm);
  this->InAlgorithm = 1;
  const int result = this->Algorithm->ProcessRequest(request, inInfo, outInfo);
  this->InAlgorithm = 0;
  if (!result && vtkSurfaceMapsErrorGuard::NumberOfReports(this->Algorithm) == reports)
  {
    vtkErrorMacro("Algorithm " << this->Algorithm->GetClassName() << "(" << this->Algorithm
                               << ") returned failure for request: " << *request);
  }
  return result;
}
