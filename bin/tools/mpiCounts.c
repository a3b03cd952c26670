/*---------------------------------------------------------------------------*\
  ldnaFoam: count a run's MPI traffic (for ldna scaling's step traffic)

  Build and use (OpenMPI's mpicc; the counts of each rank go to stderr at
  MPI_Finalize):

      mpicc -shared -fPIC -O2 -o libmpiCounts.so bin/tools/mpiCounts.c
      mpirun -np 2 -x LD_PRELOAD=$PWD/libmpiCounts.so ldnaFoam -parallel

  Run two lengths of the same window and divide the differences by the
  difference of their steps: the start-up's traffic drops out.  The MPI
  profiling interface (PMPI_*) lets these wrappers count each call and pass
  it on unchanged.
\*---------------------------------------------------------------------------*/

#include <mpi.h>
#include <stdio.h>

static long nIsend = 0, nSend = 0, nAllreduce = 0, nAlltoall = 0;
static long long bytesSent = 0;

static long long bytesOf(int count, MPI_Datatype type)
{
    int size = 0;
    MPI_Type_size(type, &size);
    return (long long)count*size;
}

int MPI_Isend(const void* buf, int count, MPI_Datatype type, int dest,
              int tag, MPI_Comm comm, MPI_Request* request)
{
    ++nIsend;
    bytesSent += bytesOf(count, type);
    return PMPI_Isend(buf, count, type, dest, tag, comm, request);
}

int MPI_Send(const void* buf, int count, MPI_Datatype type, int dest,
             int tag, MPI_Comm comm)
{
    ++nSend;
    bytesSent += bytesOf(count, type);
    return PMPI_Send(buf, count, type, dest, tag, comm);
}

int MPI_Allreduce(const void* in, void* out, int count, MPI_Datatype type,
                  MPI_Op op, MPI_Comm comm)
{
    ++nAllreduce;
    return PMPI_Allreduce(in, out, count, type, op, comm);
}

int MPI_Alltoall(const void* in, int inCount, MPI_Datatype inType, void* out,
                 int outCount, MPI_Datatype outType, MPI_Comm comm)
{
    ++nAlltoall;
    return PMPI_Alltoall(in, inCount, inType, out, outCount, outType, comm);
}

int MPI_Finalize(void)
{
    int rank = 0;
    PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
    fprintf(stderr, "mpiCounts rank %d: Isend %ld Send %ld bytes %lld "
            "Allreduce %ld Alltoall %ld\n",
            rank, nIsend, nSend, bytesSent, nAllreduce, nAlltoall);
    return PMPI_Finalize();
}
